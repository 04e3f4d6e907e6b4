#include "pipeline/io/fem_modes_state.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/pvsm_proxy.hpp"
#include "pipeline/io/xml_text.hpp"

namespace flapsim::io {

std::string mode_vector_name(int mode) {
  char name[32];
  std::snprintf(name, sizeof name, "mode_%02d", mode);
  return name;
}

std::string fem_modes_state_xml(const FemModeView& v) {
  // 256, 261, 263: ParaView's own time keeper, animation scene and time cue (updated in place).
  constexpr int kTimeKeeper = 256, kScene = 261, kTimeCue = 263;
  constexpr int kReader = 1001, kWarp = 1002, kText = 1003;
  constexpr int kRestRep = 2001, kWarpRep = 2002, kTextRep = 2003, kBar = 2004;
  constexpr int kLut = 3001, kView = 4001, kLayout = 5001;
  constexpr int kSwing = 6001, kKeyStart = 6002, kKeyEnd = 6003;
  const std::string vector = mode_vector_name(v.mode);
  std::vector<ProxyXml> p;

  ProxyXml reader("sources", "XMLUnstructuredGridReader", kReader, 1);
  reader.value("FileName", v.vtu);
  p.push_back(std::move(reader));
  ProxyXml warp("filters", "WarpByVector", kWarp, 1);
  warp.proxies("Input", {kReader}, true).values("Vectors", {"", "", "", "0", vector}).number("ScaleFactor", 1.0);
  p.push_back(std::move(warp));
  char text[256];
  std::snprintf(text, sizeof text, "mode %d: %.2f Hz, %s (shape: %s)\nlargest displacement drawn: 10 %% of the span",
                v.mode, v.frequency_hz, v.kind.c_str(), v.shape_kind.c_str());
  ProxyXml label("sources", "TextSource", kText, 1);
  label.value("Text", text);
  p.push_back(std::move(label));

  // The wing at rest, a grey outline; the warped wing coloured by |mode_NN| [m].
  ProxyXml rest("representations", "GeometryRepresentation", kRestRep, 21);
  rest.proxies("Input", {kReader}, true)
      .value("Visibility", "1")
      .value("Representation", "Outline")
      .values("ColorArrayName", {"", "", "", "0", ""})
      .numbers("DiffuseColor", {0.5, 0.5, 0.5})
      .numbers("AmbientColor", {0.5, 0.5, 0.5});
  p.push_back(std::move(rest));
  ProxyXml shape("representations", "GeometryRepresentation", kWarpRep, 21);
  shape.proxies("Input", {kWarp}, true)
      .value("Visibility", "1")
      .value("Representation", "Surface")
      .values("ColorArrayName", {"", "", "", "0", vector})
      .proxies("LookupTable", {kLut});
  p.push_back(std::move(shape));
  ProxyXml lut("lookup_tables", "PVLookupTable", kLut, 21);
  lut.value("VectorMode", "0")  // magnitude
      .numbers("RGBPoints", {0.0, 0.231373, 0.298039, 0.752941, 1.0, 0.705882, 0.0156863, 0.14902})
      .value("ScalarRangeInitialized", "0")
      .value("AutomaticRescaleRangeMode", "0");  // the data's range when loaded
  p.push_back(std::move(lut));
  ProxyXml bar("representations", "ScalarBarWidgetRepresentation", kBar, 21);
  bar.proxies("LookupTable", {kLut})
      .value("Title", "|" + vector + "| [m]")
      .value("ComponentTitle", "")
      .value("Visibility", "1")
      .value("Enabled", "1")
      .numbers("TitleColor", {0.0, 0.0, 0.0})
      .numbers("LabelColor", {0.0, 0.0, 0.0});
  p.push_back(std::move(bar));
  ProxyXml text_rep("representations", "TextSourceRepresentation", kTextRep, 21);
  text_rep.proxies("Input", {kText}, true).value("Visibility", "1").value("WindowLocation", "Upper Left Corner");
  p.push_back(std::move(text_rep));

  // From the leading edge's side, above and toward the root (z up, span along y), framing
  // the wing and its swing (± 10 % of the span up and down), parallel projection.
  const auto& b = v.bounds;
  const double c[3] = {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
  const double size = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-6});
  const double d[3] = {-0.40, -0.55, 0.73};  // toward the camera, unit
  ProxyXml view("views", "RenderView", kView, 16);
  view.proxies("Representations", {kRestRep, kWarpRep, kBar, kTextRep})
      .numbers("CameraPosition", {c[0] + 3.0 * size * d[0], c[1] + 3.0 * size * d[1], c[2] + 3.0 * size * d[2]})
      .numbers("CameraFocalPoint", {c[0], c[1], c[2]})
      .numbers("CameraViewUp", {0.0, 0.0, 1.0})
      .value("CameraParallelProjection", "1")
      .number("CameraParallelScale", 0.6 * size)
      .numbers("Background", {1.0, 1.0, 1.0})
      .value("UseColorPaletteForBackground", "0")
      .value("OrientationAxesVisibility", "1");
  p.push_back(std::move(view));

  // The swing: Warp By Vector's ScaleFactor = sin(2π s), s the animation's time 0 … 1.
  ProxyXml start("animation_keyframes", "SinusoidKeyFrame", kKeyStart, 16);
  start.number("KeyTime", 0.0).numbers("KeyValues", {1.0}).number("Frequency", 1.0).number("Phase", 0.0)
      .number("Offset", 0.0);
  p.push_back(std::move(start));
  ProxyXml end("animation_keyframes", "SinusoidKeyFrame", kKeyEnd, 16);
  end.number("KeyTime", 1.0).numbers("KeyValues", {1.0}).number("Frequency", 1.0).number("Phase", 0.0)
      .number("Offset", 0.0);
  p.push_back(std::move(end));
  ProxyXml swing("animation", "KeyFrameAnimationCue", kSwing, 16);
  swing.proxies("AnimatedProxy", {kWarp})
      .value("AnimatedPropertyName", "ScaleFactor")
      .value("AnimatedElement", "0")
      .value("Enabled", "1")
      .proxies("KeyFrames", {kKeyStart, kKeyEnd});
  p.push_back(std::move(swing));
  ProxyXml keeper("misc", "TimeKeeper", kTimeKeeper, 16);
  keeper.proxies("Views", {kView});
  p.push_back(std::move(keeper));
  ProxyXml scene("animation", "AnimationScene", kScene, 16);
  scene.proxies("TimeKeeper", {kTimeKeeper})
      .proxies("Cues", {kTimeCue, kSwing})
      .proxies("ViewModules", {kView})
      .value("PlayMode", "0")  // a sequence of frames
      .value("NumberOfFrames", "40")
      .number("StartTime", 0.0)
      .number("EndTime", 1.0)
      .value("Loop", "1");
  p.push_back(std::move(scene));
  ProxyXml cue("animation", "TimeAnimationCue", kTimeCue, 16);
  cue.proxies("AnimatedProxy", {kTimeKeeper}).value("AnimatedPropertyName", "Time").value("UseAnimationTime", "1");
  p.push_back(std::move(cue));

  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
       "<!-- flapsim modes: ParaView state animating "
    << vector
    << " (File > Load State, then Play). Files are relative to this file's folder.\n"
       "     Another mode: Warp By Vector's Vectors and the colouring to mode_NN (the text names this one). -->\n"
       "<ParaView>\n"
       "  <ServerManagerState version=\"5.11.0\">\n";
  for (const ProxyXml& q : p) x << q.str();
  x << "    <Proxy group=\"misc\" type=\"ViewLayout\" id=\"" << kLayout << "\" servers=\"20\">\n"
    << "      <Layout number_of_elements=\"1\">\n"
    << "        <Item direction=\"0\" fraction=\"0.5\" view=\"" << kView << "\"/>\n"
    << "      </Layout>\n"
    << "    </Proxy>\n";
  const auto collection = [&](const std::string& name, const std::vector<std::pair<int, std::string>>& items) {
    x << "    <ProxyCollection name=\"" << name << "\">\n";
    for (const auto& [id, item] : items) x << "      <Item id=\"" << id << "\" name=\"" << xml_attribute(item) << "\"/>\n";
    x << "    </ProxyCollection>\n";
  };
  collection("animation", {{kScene, "AnimationScene1"}, {kTimeCue, "TimeAnimationCue1"}, {kSwing, "KeyFrameAnimationCue1"}});
  collection("layouts", {{kLayout, "Layout #1"}});
  collection("lookup_tables", {{kLut, vector + ".PVLookupTable"}});
  collection("representations", {{kRestRep, "wing at rest"}, {kWarpRep, "mode shape"}, {kTextRep, "mode label"}});
  collection("scalar_bars", {{kBar, vector + " scalar bar"}});
  collection("sources", {{kReader, v.vtu}, {kWarp, "WarpByVector " + vector}, {kText, "mode label"}});
  collection("timekeeper", {{kTimeKeeper, "TimeKeeper1"}});
  collection("views", {{kView, "RenderView1"}});
  x << "    <CustomProxyDefinitions/>\n"
       "    <Links/>\n"
       "  </ServerManagerState>\n"
       "</ParaView>\n";
  return x.str();
}

void write_fem_modes_state(const std::filesystem::path& path, const FemModeView& view) {
  write_text_atomically(path, fem_modes_state_xml(view));
}

}  // namespace flapsim::io
