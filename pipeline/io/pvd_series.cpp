#include "pipeline/io/pvd_series.hpp"

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/xml_text.hpp"

#include <cstdio>
#include <ostream>

namespace flapsim::io {

namespace fs = std::filesystem;

PvdSeries::PvdSeries(fs::path path) : path_(std::move(path)) { write(); }

void PvdSeries::append(double time, const fs::path& file, int part) {
  const fs::path dir = fs::absolute(path_).parent_path().lexically_normal();
  std::string name = fs::absolute(file).lexically_normal().lexically_relative(dir).generic_string();
  if (name.empty()) name = fs::absolute(file).generic_string();  // no relative form (another root)
  entries_.push_back({time, part, std::move(name)});
}

void PvdSeries::publish() {
  if (published_ == entries_.size()) return;
  write();  // on failure the .pvd on disk still lists the previous steps
  published_ = entries_.size();
}

void PvdSeries::add(double time, const fs::path& file, int part) {
  append(time, file, part);
  try {
    publish();
  } catch (...) {
    entries_.pop_back();  // the .pvd on disk still lists the previous steps
    throw;
  }
}

std::string PvdSeries::step_file_name(std::string_view stem, long step, std::string_view extension) {
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06ld", step);
  std::string name(stem);
  name += '_';
  name += digits;
  name += '.';
  name += extension;
  return name;
}

void PvdSeries::write() const {
  write_file_atomically(path_, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const Entry& e : entries_)
      out << "    <DataSet timestep=\"" << format_number(e.time) << "\" group=\"\" part=\"" << e.part
          << "\" file=\"" << xml_attribute(e.file) << "\"/>\n";
    out << "  </Collection>\n"
           "</VTKFile>\n";
  });
}

}  // namespace flapsim::io
