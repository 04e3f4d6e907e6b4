#pragma once
// One <Proxy> of a ParaView state file (.pvsm): its properties as element values or
// proxy references, the XML ParaView 5.11's "Load State" reads (pvsm_state.hpp,
// fem_modes_state.hpp).

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/xml_text.hpp"

namespace flapsim::io {

class ProxyXml {
 public:
  ProxyXml(std::string group, std::string type, int id, int servers)
      : group_(std::move(group)), type_(std::move(type)), id_(id), servers_(servers) {}

  ProxyXml& values(const std::string& name, const std::vector<std::string>& v) {
    body_ << "      <Property name=\"" << name << "\" id=\"" << id_ << "." << name << "\" number_of_elements=\""
          << v.size() << "\">\n";
    for (std::size_t i = 0; i < v.size(); ++i)
      body_ << "        <Element index=\"" << i << "\" value=\"" << xml_attribute(v[i]) << "\"/>\n";
    body_ << "      </Property>\n";
    return *this;
  }
  ProxyXml& value(const std::string& name, const std::string& v) { return values(name, {v}); }
  ProxyXml& number(const std::string& name, double v) { return values(name, {format_number(v)}); }
  ProxyXml& numbers(const std::string& name, const std::vector<double>& v) {
    std::vector<std::string> s;
    for (double x : v) s.push_back(format_number(x));
    return values(name, s);
  }
  ProxyXml& proxies(const std::string& name, const std::vector<int>& ids, bool output_port = false) {
    body_ << "      <Property name=\"" << name << "\" id=\"" << id_ << "." << name << "\" number_of_elements=\""
          << ids.size() << "\">\n";
    for (int i : ids)
      body_ << "        <Proxy value=\"" << i << "\"" << (output_port ? " output_port=\"0\"" : "") << "/>\n";
    body_ << "      </Property>\n";
    return *this;
  }
  std::string str() const {
    return "    <Proxy group=\"" + group_ + "\" type=\"" + type_ + "\" id=\"" + std::to_string(id_) +
           "\" servers=\"" + std::to_string(servers_) + "\">\n" + body_.str() + "    </Proxy>\n";
  }

 private:
  std::string group_, type_;
  int id_, servers_;
  std::ostringstream body_;
};

}  // namespace flapsim::io
