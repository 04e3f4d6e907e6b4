#include "pipeline/io/pvsm_state.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/pvsm_proxy.hpp"
#include "pipeline/io/xml_text.hpp"

namespace flapsim::io {

namespace {

// ParaView's "Cool to Warm" diverging map over [-range, range] (blue, grey, red), fixed:
// no rescaling when the time changes (AutomaticRescaleRangeMode -1, "Never").
ProxyXml diverging_lookup_table(int id, double range) {
  ProxyXml lut("lookup_tables", "PVLookupTable", id, 21);
  lut.numbers("RGBPoints", {-range, 0.231373, 0.298039, 0.752941, 0.0, 0.865003, 0.865003, 0.865003, range,
                            0.705882, 0.0156863, 0.14902})
      .value("ColorSpace", "3")  // diverging
      .value("ScalarRangeInitialized", "1")
      .value("AutomaticRescaleRangeMode", "-1");
  return lut;
}

// A sequential map of a vector's magnitude over [0, range]: white at rest to dark blue
// (render_run.py's FEM colours), fixed as the diverging map.
ProxyXml magnitude_lookup_table(int id, double range) {
  ProxyXml lut("lookup_tables", "PVLookupTable", id, 21);
  lut.numbers("RGBPoints", {0.0, 1.0, 1.0, 1.0, range, 0.1, 0.25, 0.6})
      .value("ColorSpace", "0")  // RGB
      .value("VectorMode", "0")  // magnitude
      .value("ScalarRangeInitialized", "1")
      .value("AutomaticRescaleRangeMode", "-1");
  return lut;
}

// The side view: along the span at mid-stroke, from beyond the tip (+y), level with the
// stroke plane: the stroke seen edge-on and the wake below it.
ViewDirection side_view() { return {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}; }

}  // namespace

std::array<double, 6> state_box(const RunState& s) {
  const double L = s.length_scale;
  std::array<double, 6> box = s.bounds.value_or(std::array<double, 6>{-L, L, -L, L, -L, L});
  box[4] -= 0.15 * L;  // the near wake below the stroke
  return box;
}

std::optional<double> state_start_time(const std::vector<double>& frame_times, double period) {
  if (frame_times.empty()) return std::nullopt;
  const double last = frame_times.back();
  if (!(period > 0.0)) return last;
  constexpr double kPhase = 0.25;
  const double cycles = last / period;
  // The latest t/T = n + 0.25 not after the last frame; none in a run this short: its last frame.
  const double n = std::floor(cycles - kPhase + 1e-9);
  if (n < 0.0) return last;
  const double target = (n + kPhase) * period;
  return *std::min_element(frame_times.begin(), frame_times.end(),
                           [&](double a, double b) { return std::abs(a - target) < std::abs(b - target); });
}

double magnitude_percentile(std::vector<double>& values, double p) {
  if (values.empty()) return 0.0;
  for (double& v : values) v = std::abs(v);
  const auto n = values.size();
  auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(n)));
  rank = std::clamp<std::size_t>(rank, 1, n);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank - 1), values.end());
  return values[rank - 1];
}

std::string run_state_xml(const RunState& s) {
  // Proxy ids: 256, 261, 263 are ParaView's own time keeper, animation scene and time
  // cue, which loading a state updates in place; the others are this file's.
  constexpr int kTimeKeeper = 256, kScene = 261, kTimeCue = 263;
  constexpr int kWingReader = 1001, kWakeReader = 1002, kChainReader = 1003, kLiftOverTime = 1004;
  constexpr int kChartRep = 2004;
  constexpr int kWingLut = 3001, kCirculationLut = 3002, kDisplacementLut = 3003;
  constexpr int kRenderView = 4001, kChartView = 4002, kSideView = 4003, kLayout = 5001;

  std::vector<ProxyXml> proxies;
  std::vector<std::pair<int, std::string>> sources, representations, luts, scalar_bars;
  std::vector<int> readers;

  const auto reader = [&](int id, const std::string& file) {
    ProxyXml r("sources", "PVDReader", id, 1);
    r.value("FileName", file);
    proxies.push_back(std::move(r));
    sources.emplace_back(id, file);
    readers.push_back(id);
  };
  if (s.air) {
    reader(kWingReader, s.wing_pvd);
    reader(kWakeReader, s.wake_pvd);
  }
  reader(kChainReader, s.chain_pvd);
  const bool cp = s.wing_field == "Cp";
  if (s.air) {
    proxies.push_back(diverging_lookup_table(kWingLut, s.wing_range));
    luts.emplace_back(kWingLut, s.wing_field + ".PVLookupTable");
    proxies.push_back(diverging_lookup_table(kCirculationLut, s.circulation_range));
    luts.emplace_back(kCirculationLut, "circulation_m2_s.PVLookupTable");
  }
  const bool fem_in_vacuum = s.structure_mesh && !s.air;
  if (fem_in_vacuum) {
    proxies.push_back(magnitude_lookup_table(kDisplacementLut, s.displacement_range));
    luts.emplace_back(kDisplacementLut, "displacement_m.PVLookupTable");
  }

  // The representations of one 3-D view (ids base + 1 …; a representation belongs to one
  // view): the wing coloured by wing_field with its panel edges, the wake's vortex lines
  // coloured by circulation, translucent, the chain as thick black lines (a FEM's mesh:
  // RunState::structure_mesh); a scalar bar
  // for each coloured one. Returns the ids the view lists.
  const auto view_representations = [&](int base, const std::string& view_name) {
    std::vector<int> shown;
    const auto representation = [&](int id, int input, const std::string& name) {
      ProxyXml r("representations", "GeometryRepresentation", id, 21);
      r.proxies("Input", {input}, true).value("Visibility", "1");
      representations.emplace_back(id, name + " (" + view_name + ")");
      shown.push_back(id);
      return r;
    };
    const auto scalar_bar = [&](int id, int lut, const std::string& title, const std::vector<double>& position) {
      ProxyXml bar("representations", "ScalarBarWidgetRepresentation", id, 21);
      bar.proxies("LookupTable", {lut})
          .value("Title", title)
          .value("ComponentTitle", "")
          .value("Visibility", "1")
          .value("Enabled", "1")
          .value("WindowLocation", "Any Location")
          .numbers("Position", position)
          .number("ScalarBarLength", 0.4)
          .numbers("TitleColor", {0.0, 0.0, 0.0})
          .numbers("LabelColor", {0.0, 0.0, 0.0});
      proxies.push_back(std::move(bar));
      scalar_bars.emplace_back(id, title + " (" + view_name + ")");
      shown.push_back(id);
    };
    if (s.air) {
      ProxyXml wing = representation(base + 1, kWingReader, "wing");
      wing.value("Representation", "Surface With Edges")
          .values("ColorArrayName", {"", "", "", "1", s.wing_field})
          .proxies("LookupTable", {kWingLut});
      proxies.push_back(std::move(wing));
      ProxyXml wake = representation(base + 2, kWakeReader, "wake");
      wake.value("Representation", "Wireframe")
          .values("ColorArrayName", {"", "", "", "1", "circulation_m2_s"})
          .proxies("LookupTable", {kCirculationLut})
          .number("Opacity", 0.35)
          .number("LineWidth", 1.0)
          .number("Ambient", 1.0)  // unlit: a line's colour is its circulation's, whatever its angle
          .number("Diffuse", 0.0);
      proxies.push_back(std::move(wake));
    }
    ProxyXml chain = representation(base + 3, kChainReader, s.structure_mesh ? "FEM" : "chain");
    if (!s.structure_mesh)
      chain.value("Representation", "Wireframe")
          .values("ColorArrayName", {"", "", "", "0", ""})
          .numbers("DiffuseColor", {0.0, 0.0, 0.0})
          .numbers("AmbientColor", {0.0, 0.0, 0.0})
          .number("LineWidth", 4.0);
    else if (s.air)
      chain.value("Representation", "Wireframe")
          .values("ColorArrayName", {"", "", "", "0", ""})
          .numbers("DiffuseColor", {0.2, 0.2, 0.2})
          .numbers("AmbientColor", {0.2, 0.2, 0.2})
          .number("Opacity", 0.25)
          .number("LineWidth", 1.0);
    else  // coloured by |displacement_m| (point data); its thousands of edges would hide it
      chain.value("Representation", "Surface")
          .values("ColorArrayName", {"", "", "", "0", "displacement_m"})
          .proxies("LookupTable", {kDisplacementLut})
          .number("LineWidth", 2.0);
    proxies.push_back(std::move(chain));
    if (fem_in_vacuum) scalar_bar(base + 4, kDisplacementLut, "|displacement| [m]", {0.89, 0.52});
    if (s.air) {
      scalar_bar(base + 4, kWingLut, cp ? "Cp" : "pressure jump [Pa]", {0.89, 0.52});
      scalar_bar(base + 5, kCirculationLut, "circulation [m^2/s]", {0.89, 0.05});
    }
    return shown;
  };

  // Cameras with parallel projection that frame the box (state_box) in a view of
  // kStateViewWidth x kStateViewHeight.
  const std::array<double, 6> box = state_box(s);
  const auto camera = [&](ProxyXml& view, const ViewDirection& d) {
    const FramingCamera c = frame_box(box, d, static_cast<double>(kStateViewWidth) / kStateViewHeight);
    view.numbers("CameraPosition", {c.position[0], c.position[1], c.position[2]})
        .numbers("CameraFocalPoint", {c.focal_point[0], c.focal_point[1], c.focal_point[2]})
        .numbers("CameraViewUp", {c.up[0], c.up[1], c.up[2]})
        .value("CameraParallelProjection", "1")
        .number("CameraParallelScale", c.parallel_scale)
        .numbers("CenterOfRotation", {c.focal_point[0], c.focal_point[1], c.focal_point[2]})
        .values("ViewSize", {std::to_string(kStateViewWidth), std::to_string(kStateViewHeight)})
        .numbers("Background", {1.0, 1.0, 1.0})
        .value("UseColorPaletteForBackground", "0")
        .value("OrientationAxesVisibility", "1");
  };
  ProxyXml view("views", "RenderView", kRenderView, 16);
  view.proxies("Representations", view_representations(2100, "front"));
  camera(view, s.front);
  proxies.push_back(std::move(view));
  ProxyXml side("views", "RenderView", kSideView, 16);
  side.proxies("Representations", view_representations(2200, "side"));
  camera(side, side_view());
  proxies.push_back(std::move(side));

  // Lift over time: the field data of every step of the first series, one table whose
  // columns are the frames' field data and ParaView's Time; lift_N and CL drawn against
  // t/T, every other column named hidden (ParaView draws a column the state does not name).
  const int timed = s.air ? kWingReader : kChainReader;
  ProxyXml over_time("filters", "ExtractFieldDataOverTime", kLiftOverTime, 1);
  over_time.proxies("Input", {timed}, true).value("AutoDetectGlobalTemporalDataArrays", "0");
  proxies.push_back(std::move(over_time));
  sources.emplace_back(kLiftOverTime, "lift over time");
  std::vector<std::string> columns = s.frame_fields;
  for (const char* c : {"Time", "TimeValue", "N", "vtkValidPointMask", "step", "t_over_T"})
    if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.emplace_back(c);
  for (const std::string& c : state_chart_series())
    if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
  std::vector<std::string> visibility, corner, colour, label;
  for (const std::string& c : columns) {
    const bool lift = c == "lift_N", cl = c == "CL";
    visibility.insert(visibility.end(), {c, lift || cl ? "1" : "0"});
    if (lift) {
      corner.insert(corner.end(), {c, "0"});  // left axis
      colour.insert(colour.end(), {c, "0", "0", "0"});
      label.insert(label.end(), {c, "lift [N]"});
    } else if (cl) {
      corner.insert(corner.end(), {c, "1"});  // right axis
      colour.insert(colour.end(), {c, "0.231373", "0.298039", "0.752941"});
      label.insert(label.end(), {c, "CL"});
    }
  }
  ProxyXml chart_rep("representations", "XYChartRepresentation", kChartRep, 21);
  chart_rep.proxies("Input", {kLiftOverTime}, true)
      .value("Visibility", "1")
      .value("AttributeType", "6")  // row data of the table
      .value("UseIndexForXAxis", "0")
      .value("XArrayName", "t_over_T")
      .values("SeriesVisibility", visibility)
      .values("SeriesPlotCorner", corner)
      .values("SeriesColor", colour)
      .values("SeriesLabel", label);
  proxies.push_back(std::move(chart_rep));
  representations.emplace_back(kChartRep, "lift over time chart");
  ProxyXml chart("views", "XYChartView", kChartView, 16);
  chart.proxies("Representations", {kChartRep})
      .value("ChartTitle", s.air ? "lift and CL" : "lift (vacuum: none)")
      .value("LeftAxisTitle", "lift [N]")
      .value("RightAxisTitle", "CL")
      .value("BottomAxisTitle", "t/T")
      .value("HideTimeMarker", "1");  // the marker sits at t [s], the axis is t/T
  proxies.push_back(std::move(chart));

  ProxyXml keeper("misc", "TimeKeeper", kTimeKeeper, 16);
  keeper.proxies("TimeSources", readers).proxies("Views", {kRenderView, kSideView, kChartView});
  ProxyXml scene("animation", "AnimationScene", kScene, 16);
  scene.proxies("TimeKeeper", {kTimeKeeper})
      .proxies("Cues", {kTimeCue})
      .proxies("ViewModules", {kRenderView, kSideView, kChartView})
      .value("PlayMode", "2");  // snap to the time steps of the series
  if (s.start_time) {           // open on a frame of the last wingbeat, not on t = 0 (no loads, no wake)
    keeper.value("Time", format_number(*s.start_time));
    scene.value("AnimationTime", format_number(*s.start_time));
  }
  proxies.push_back(std::move(keeper));
  proxies.push_back(std::move(scene));
  ProxyXml cue("animation", "TimeAnimationCue", kTimeCue, 16);
  cue.proxies("AnimatedProxy", {kTimeKeeper}).value("AnimatedPropertyName", "Time").value("UseAnimationTime", "1");
  proxies.push_back(std::move(cue));

  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
       "<!-- flapsim run: ParaView state (File > Load State). Files are relative to this file's folder.\n"
       "     Colour ranges: +/- the "
    << format_number(s.percentile) << "th percentile of |" << s.wing_field
    << "| (wing) and |circulation_m2_s| (wake) over the frames written. -->\n"
       "<ParaView>\n"
       "  <ServerManagerState version=\"5.11.0\">\n";
  for (const ProxyXml& p : proxies) x << p.str();
  // The layout: on the left (60 %) the front view above the side view, the chart on the right.
  x << "    <Proxy group=\"misc\" type=\"ViewLayout\" id=\"" << kLayout << "\" servers=\"20\">\n"
    << "      <Layout number_of_elements=\"5\">\n"
    << "        <Item direction=\"2\" fraction=\"0.6\" view=\"0\"/>\n"
    << "        <Item direction=\"1\" fraction=\"0.6\" view=\"0\"/>\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kChartView << "\"/>\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kRenderView << "\"/>\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kSideView << "\"/>\n"
    << "      </Layout>\n"
    << "    </Proxy>\n";
  const auto collection = [&](const std::string& name, const std::vector<std::pair<int, std::string>>& items) {
    x << "    <ProxyCollection name=\"" << name << "\">\n";
    for (const auto& [id, item] : items) x << "      <Item id=\"" << id << "\" name=\"" << xml_attribute(item) << "\"/>\n";
    x << "    </ProxyCollection>\n";
  };
  collection("animation", {{kScene, "AnimationScene1"}, {kTimeCue, "TimeAnimationCue1"}});
  collection("layouts", {{kLayout, "Layout #1"}});
  collection("lookup_tables", luts);
  collection("representations", representations);
  collection("scalar_bars", scalar_bars);
  collection("sources", sources);
  collection("timekeeper", {{kTimeKeeper, "TimeKeeper1"}});
  collection("views", {{kRenderView, "RenderView1"}, {kSideView, "RenderView2"}, {kChartView, "LineChartView1"}});
  x << "    <CustomProxyDefinitions/>\n"
       "    <Links/>\n"
       "  </ServerManagerState>\n"
       "</ParaView>\n";
  return x.str();
}

void write_run_state(const std::filesystem::path& path, const RunState& state) {
  write_text_atomically(path, run_state_xml(state));
}

}  // namespace flapsim::io
