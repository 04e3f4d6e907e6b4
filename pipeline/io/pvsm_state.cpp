#include "pipeline/io/pvsm_state.hpp"

#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/xml_text.hpp"

namespace flapsim::io {

namespace {

// One <Proxy> of the state: its properties as element values or proxy references.
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

// ParaView's "Cool to Warm" diverging map over [-range, range] (blue, grey, red).
ProxyXml diverging_lookup_table(int id, double range) {
  ProxyXml lut("lookup_tables", "PVLookupTable", id, 21);
  lut.numbers("RGBPoints", {-range, 0.231373, 0.298039, 0.752941, 0.0, 0.865003, 0.865003, 0.865003, range,
                            0.705882, 0.0156863, 0.14902})
      .value("ColorSpace", "3")  // diverging
      .value("ScalarRangeInitialized", "1")
      .value("AutomaticRescaleRangeMode", "1");  // grow and update every time step
  return lut;
}

}  // namespace

std::string run_state_xml(const RunState& s) {
  // Proxy ids: 256, 261, 263 are ParaView's own time keeper, animation scene and time
  // cue, which loading a state updates in place; the others are this file's.
  constexpr int kTimeKeeper = 256, kScene = 261, kTimeCue = 263;
  constexpr int kWingReader = 1001, kWakeReader = 1002, kChainReader = 1003, kLiftOverTime = 1004;
  constexpr int kWingRep = 2001, kWakeRep = 2002, kChainRep = 2003, kChartRep = 2004;
  constexpr int kPressureLut = 3001, kCirculationLut = 3002;
  constexpr int kRenderView = 4001, kChartView = 4002, kLayout = 5001;

  std::vector<ProxyXml> proxies;
  std::vector<std::pair<int, std::string>> sources, representations, luts;
  std::vector<int> readers, shown;

  const auto reader = [&](int id, const std::string& file) {
    ProxyXml r("sources", "PVDReader", id, 1);
    r.value("FileName", file);
    proxies.push_back(std::move(r));
    sources.emplace_back(id, file);
    readers.push_back(id);
  };
  const auto representation = [&](int id, int input, const std::string& name) {
    ProxyXml r("representations", "GeometryRepresentation", id, 21);
    r.proxies("Input", {input}, true).value("Visibility", "1");
    representations.emplace_back(id, name);
    shown.push_back(id);
    return r;
  };

  if (s.air) {
    reader(kWingReader, s.wing_pvd);
    reader(kWakeReader, s.wake_pvd);
  }
  reader(kChainReader, s.chain_pvd);

  if (s.air) {
    // The wing coloured by the pressure jump (cell data), with its panel edges.
    ProxyXml wing = representation(kWingRep, kWingReader, "wing");
    wing.value("Representation", "Surface With Edges")
        .values("ColorArrayName", {"", "", "", "1", "pressure_jump_Pa"})
        .proxies("LookupTable", {kPressureLut});
    proxies.push_back(std::move(wing));
    proxies.push_back(diverging_lookup_table(kPressureLut, s.pressure_range));
    luts.emplace_back(kPressureLut, "pressure_jump_Pa.PVLookupTable");
    // The wake coloured by circulation, half transparent.
    ProxyXml wake = representation(kWakeRep, kWakeReader, "wake");
    wake.value("Representation", "Surface")
        .values("ColorArrayName", {"", "", "", "1", "circulation_m2_s"})
        .proxies("LookupTable", {kCirculationLut})
        .number("Opacity", 0.5);
    proxies.push_back(std::move(wake));
    proxies.push_back(diverging_lookup_table(kCirculationLut, s.circulation_range));
    luts.emplace_back(kCirculationLut, "circulation_m2_s.PVLookupTable");
  }
  // The chain as thick black lines.
  ProxyXml chain = representation(kChainRep, kChainReader, "chain");
  chain.value("Representation", "Wireframe")
      .values("ColorArrayName", {"", "", "", "0", ""})
      .numbers("DiffuseColor", {0.0, 0.0, 0.0})
      .numbers("AmbientColor", {0.0, 0.0, 0.0})
      .number("LineWidth", 4.0);
  proxies.push_back(std::move(chain));

  // Lift over time: the field data of every step of the first series, one table.
  const int timed = s.air ? kWingReader : kChainReader;
  ProxyXml over_time("filters", "ExtractFieldDataOverTime", kLiftOverTime, 1);
  over_time.proxies("Input", {timed}, true).value("AutoDetectGlobalTemporalDataArrays", "0");
  proxies.push_back(std::move(over_time));
  sources.emplace_back(kLiftOverTime, "lift over time");
  ProxyXml chart_rep("representations", "XYChartRepresentation", kChartRep, 21);
  chart_rep.proxies("Input", {kLiftOverTime}, true)
      .value("Visibility", "1")
      .value("AttributeType", "6")  // row data of the table
      .value("UseIndexForXAxis", "0")
      .value("XArrayName", "Time")
      .values("SeriesVisibility", {s.air ? "lift_N" : "t_over_T", "1"});
  proxies.push_back(std::move(chart_rep));
  representations.emplace_back(kChartRep, "lift over time chart");

  // The 3-D view, looking at the stroke plane from above and in front.
  const double L = s.length_scale;
  ProxyXml view("views", "RenderView", kRenderView, 16);
  view.proxies("Representations", shown)
      .numbers("CameraPosition", {1.6 * L, -2.0 * L, 1.6 * L})
      .numbers("CameraFocalPoint", {0.0, 0.0, 0.0})
      .numbers("CameraViewUp", {0.0, 0.0, 1.0})
      .number("CameraParallelScale", 1.2 * L)
      .value("OrientationAxesVisibility", "1");
  proxies.push_back(std::move(view));
  ProxyXml chart("views", "XYChartView", kChartView, 16);
  chart.proxies("Representations", {kChartRep})
      .values("LeftAxisTitle", {s.air ? "lift [N]" : "t/T"})
      .values("BottomAxisTitle", {"t [s]"})
      .value("HideTimeMarker", "0");
  proxies.push_back(std::move(chart));

  ProxyXml keeper("misc", "TimeKeeper", kTimeKeeper, 16);
  keeper.proxies("TimeSources", readers).proxies("Views", {kRenderView, kChartView});
  proxies.push_back(std::move(keeper));
  ProxyXml scene("animation", "AnimationScene", kScene, 16);
  scene.proxies("TimeKeeper", {kTimeKeeper})
      .proxies("Cues", {kTimeCue})
      .proxies("ViewModules", {kRenderView, kChartView})
      .value("PlayMode", "2");  // snap to the time steps of the series
  proxies.push_back(std::move(scene));
  ProxyXml cue("animation", "TimeAnimationCue", kTimeCue, 16);
  cue.proxies("AnimatedProxy", {kTimeKeeper}).value("AnimatedPropertyName", "Time").value("UseAnimationTime", "1");
  proxies.push_back(std::move(cue));

  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
       "<!-- flapsim run: ParaView state (File > Load State). Files are relative to this file's folder. -->\n"
       "<ParaView>\n"
       "  <ServerManagerState version=\"5.11.0\">\n";
  for (const ProxyXml& p : proxies) x << p.str();
  // The layout: the 3-D view on the left (60 %), the chart on the right.
  x << "    <Proxy group=\"misc\" type=\"ViewLayout\" id=\"" << kLayout << "\" servers=\"20\">\n"
    << "      <Layout number_of_elements=\"3\">\n"
    << "        <Item direction=\"2\" fraction=\"0.6\" view=\"0\"/>\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kRenderView << "\"/>\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kChartView << "\"/>\n"
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
  collection("sources", sources);
  collection("timekeeper", {{kTimeKeeper, "TimeKeeper1"}});
  collection("views", {{kRenderView, "RenderView1"}, {kChartView, "LineChartView1"}});
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
