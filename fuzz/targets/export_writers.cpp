// Fuzz target: the export writers (sensors.urdf.xacro, nav2_costmap.yaml, self_filters.yaml,
// the launch file) given hostile text where a robot description or a command line puts it:
// link names, the base frame, the header (paths, the rig's name). Mount ids and topics are
// ROS names (the rig loader and the options refuse others), made here from the same bytes.
// Each file must parse (tinyxml2, yaml-cpp) and carry every name back exactly.
#include <tinyxml2.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_launch_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_writer.hpp"

namespace {

// Characters that break formats written raw; free text (the header) also takes every byte.
constexpr char kHostile[] = "ab_/\"'<>&-#:{}()[],*!%@`|\\$.?=";

struct Bytes {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;
  // The next field: up to a 0 byte, each byte mapped into `alphabet` (all bytes when null).
  std::string field(const char* alphabet, std::size_t alphabet_size) {
    std::string text;
    while (at < size && data[at] != 0 && text.size() < 40) {
      const std::uint8_t byte = data[at++];
      text += alphabet ? alphabet[byte % alphabet_size] : static_cast<char>(byte);
    }
    ++at;
    return text;
  }
  std::string hostile() {
    std::string text = field(kHostile, sizeof kHostile - 1);
    return text.empty() ? "x" : text;
  }
  std::string ros_name() {  // letters and digits after a letter: a ROS name token
    static constexpr char kName[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    return "m" + field(kName, sizeof kName - 1);
  }
};

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "export writers: %s\n", what.c_str());
  std::abort();
}

// What xacro reads from attribute text: a run of two or more '$' before '{' or '(' loses one
// '$' (xacro's DOLLAR_DOLLAR_BRACE token); a single '$' there starts an expression, which a
// name the writer copies must never become.
std::optional<std::string> xacro_unescaped(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] != '$') {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && text[end] == '$') ++end;
    const bool brace = end < text.size() && (text[end] == '{' || text[end] == '(');
    if (brace && end - i == 1) return std::nullopt;
    out.append(brace ? end - i - 1 : end - i, '$');
    i = end;
  }
  return out;
}

void check_xacro(const std::string& text, const rigdesign::deploy::SensorFrames& frames) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    finding(std::string("sensors.urdf.xacro does not parse: ") + document.ErrorStr());
  std::set<std::string> children;
  std::vector<const tinyxml2::XMLElement*> stack = {document.RootElement()};
  while (!stack.empty()) {
    const tinyxml2::XMLElement* element = stack.back();
    stack.pop_back();
    if (!element) continue;
    if (std::string(element->Name()) == "joint") {
      const tinyxml2::XMLElement* child = element->FirstChildElement("child");
      if (child && child->Attribute("link")) {
        std::string link = child->Attribute("link");
        if (link.rfind("${prefix}", 0) == 0) link = link.substr(9);
        const auto read = xacro_unescaped(link);
        if (!read) finding("a link name became a xacro expression: " + link);
        children.insert(*read);
      }
    }
    for (const tinyxml2::XMLElement* c = element->FirstChildElement(); c;
         c = c->NextSiblingElement())
      stack.push_back(c);
  }
  for (const rigdesign::deploy::SensorFrame& frame : frames.frames) {
    if (!children.count(frame.link)) finding("the link '" + frame.link + "' did not come back");
  }
  // Joints hang from ${parent}, whose default the params attribute states.
  const tinyxml2::XMLElement* macro = document.RootElement()->FirstChildElement("xacro:macro");
  const char* params = macro ? macro->Attribute("params") : nullptr;
  const std::string stated = params ? params : "";
  const std::size_t space = stated.find(' ');
  const auto parent = stated.rfind("parent:=", 0) == 0 && space != std::string::npos
                          ? xacro_unescaped(stated.substr(8, space - 8))
                          : std::nullopt;
  if (!parent || *parent != frames.parent)
    finding("the parent '" + frames.parent + "' did not come back: " + stated);
}

void check_nav2(const std::string& text, const rigdesign::deploy::CostmapConfig& config) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    finding(std::string("nav2_costmap.yaml does not parse: ") + error.what());
  }
  const YAML::Node parameters = root["local_costmap"]["local_costmap"]["ros__parameters"];
  if (!parameters || parameters["robot_base_frame"].as<std::string>() != config.robot_base_frame)
    finding("robot_base_frame did not come back");
}

void check_filters(const std::string& text, const std::string& frame) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    finding(std::string("self_filters.yaml does not parse: ") + error.what());
  }
  for (const auto& node : root) {
    const YAML::Node parameters = node.second["ros__parameters"];
    if (parameters && parameters["input_frame"] &&
        parameters["input_frame"].as<std::string>() != frame)
      finding("a crop box's input_frame did not come back");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rigdesign;
  Bytes bytes{data, size};
  const std::string header = bytes.field(nullptr, 0);  // any byte: paths, the rig's name
  deploy::SensorFrames frames;
  frames.parent = bytes.hostile();
  deploy::CostmapConfig config;
  config.robot_base_frame = bytes.hostile();
  config.notes = {header};
  std::vector<deploy::SelfFilter> filters;
  std::set<std::string> ids;
  for (int k = 0; k < 4 && bytes.at < size; ++k) {
    const std::string id = bytes.ros_name() + std::to_string(k);
    ids.insert(id);
    deploy::SensorFrame frame;
    frame.mount_id = id;
    frame.sensor_id = bytes.hostile();
    frame.mode_id = bytes.hostile();
    frame.link = bytes.hostile() + std::to_string(k);  // links of a description are unique
    frame.joint = frame.link + "_joint";
    frame.data_frame = frame.link;
    frame.note = header;
    frames.frames.push_back(frame);
    deploy::SourceConfig source;
    source.mount_id = id;
    source.laser_scan = k % 2 == 0;
    source.raw_topic = "/" + id + "/raw";
    source.topic = "/" + id + "/filtered";
    source.sensor_frame = frame.link;
    source.topic_note = header;
    config.sources.push_back(source);
    deploy::SelfFilter filter;
    filter.mount_id = id;
    filter.scanner = source.laser_scan;
    if (filter.scanner) {
      filter.bands = {{-0.5, 0.5}};
    } else {
      filter.boxes = {{frame.link, model::Vec3(-1, -1, 0), model::Vec3(1, 1, 1), 10}};
    }
    filters.push_back(filter);
  }
  try {
    check_xacro(deploy::sensors_xacro_text(frames, header), frames);
  } catch (const model::InputError& error) {  // a parent with a space: refused, with a message
    fuzz::require_clear_message(error);
  }
  check_nav2(deploy::nav2_costmap_text(config, header), config);
  check_filters(
      deploy::self_filters_text(filters, config.robot_base_frame, model::Pose3::Identity(), header),
      config.robot_base_frame);
  (void)deploy::self_filters_launch_text(filters, config.sources, "self_filters.yaml", header);
  return 0;
}
