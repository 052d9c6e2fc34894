#include "rigdesign/studio/studio_api.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_clearance.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/fov_mesh.hpp"
#include "rigdesign/render/gltf_scene.hpp"
#include "rigdesign/report/json_report.hpp"
#include "rigdesign/report/sensor_query.hpp"
#include "rigdesign/studio/request_guard.hpp"

namespace rigdesign::studio {
namespace {

using nlohmann::json;

// A request the page should not send: 400 with what was wrong.
struct BadRequest {
  std::string what;
};

// JSON with its charset, sent as is: the studio compresses nothing (on the earlier server,
// cpp-httplib, Brotli took 150 ms of a 113 kB pose update on a loopback that needs none).
studio::Reply json_reply(const json& value, int status = 200) {
  return {status, "application/json; charset=utf-8", value.dump()};
}

std::array<double, 3> triple_field(const json& body, const char* key) {
  if (!body.contains(key) || !body[key].is_array() || body[key].size() != 3)
    throw BadRequest{std::string(key) + " must be a list of three numbers"};
  std::array<double, 3> values{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!body[key][i].is_number() || !std::isfinite(body[key][i].get<double>()))
      throw BadRequest{std::string(key) + " must be a list of three finite numbers"};
    values[i] = body[key][i].get<double>();
  }
  return values;
}

std::string text_field(const json& body, const char* key) {
  if (!body.contains(key) || !body[key].is_string())
    throw BadRequest{std::string(key) + " must be a string"};
  return body[key].get<std::string>();
}

studio::MountPose pose_in(const json& body) {
  return {triple_field(body, "xyz"), triple_field(body, "rpy_deg")};
}

json diagnostics_json(const std::vector<model::Diagnostic>& diagnostics) {
  json list = json::array();
  for (const model::Diagnostic& d : diagnostics) list.push_back(report::to_json(d));
  return list;
}

json mounts_json(const studio::StudioSession& session) {
  json mounts = json::array();
  for (const model::Mount& mount : session.inputs().rig.mounts) {
    const studio::MountPose pose = session.pose(mount);
    mounts.push_back({{"id", mount.id},
                      {"sensor", mount.sensor_id},
                      {"mode", mount.mode_id},
                      {"xyz", pose.xyz},
                      {"rpy_deg", pose.rpy_deg},
                      {"urdf_link", mount.urdf_link}});
  }
  return mounts;
}

// `metrics --format json`'s coverage summaries with the curves as three plain lists: a pose update
// is a third the size of the per-angle records `report::to_json(coverage, true)` gives.
json coverage_json(const metrics::RigCoverage& coverage) {
  json report = report::to_json(coverage, false);
  json theta = json::array(), complete = json::array(), floor = json::array();
  for (const metrics::AngleCoverage& angle : coverage.angles) {
    theta.push_back(model::rad_to_deg(angle.theta));
    complete.push_back(angle.complete);
    floor.push_back(angle.floor);
  }
  report["curve_theta_deg"] = theta;
  report["curve_complete"] = complete;
  report["curve_floor"] = floor;
  return report;
}

// `since`: when the request arrived, so `seconds` covers the edit (the moved mount's rasters)
// and the numbers; `compute_seconds` the numbers alone.
json numbers_json(const studio::StudioSession& session, bool exact,
                  std::chrono::steady_clock::time_point since) {
  const studio::StudioNumbers numbers = session.numbers(exact);
  json requirements = json::array();
  for (const metrics::RequirementResult& result : numbers.requirements) {
    json item = report::to_json(result);
    const std::optional<double> margin = result.margin();
    item["margin"] = margin ? json(*margin) : json(nullptr);
    requirements.push_back(std::move(item));
  }
  json sectors = json::array();
  for (const metrics::SectorCoverage& sector : numbers.coverage.sectors) {
    sectors.push_back({{"name", sector.sector.name},
                       {"from_deg", model::rad_to_deg(sector.sector.from)},
                       {"to_deg", model::rad_to_deg(sector.sector.to)}});
  }
  return {
      {"exact", exact},
      {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count()},
      {"compute_seconds", numbers.seconds},
      {"metrics", report::to_json(session.inputs(), numbers.resultant)},
      {"coverage", coverage_json(numbers.coverage)},
      {"sector_bounds", sectors},
      {"requirements", requirements},
      {"mounts", mounts_json(session)},
      {"dirty", session.dirty()}};
}

json library_json(const model::SensorLibrary& library) {
  json sensors = json::array();
  for (const model::Sensor& sensor : library.sensors) {
    json modes = json::array();
    for (const model::SensorMode& mode : sensor.modes) modes.push_back(mode.id);
    sensors.push_back({{"id", sensor.id},
                       {"name", sensor.name},
                       {"technology", to_string(sensor.technology)},
                       {"price_usd", sensor.price.usd},
                       {"modes", modes}});
  }
  return sensors;
}

json state_json(const studio::StudioSession& session, std::chrono::steady_clock::time_point since) {
  json state = {{"rig_file", session.rig_path()},
                {"loaded", session.loaded()},
                {"diagnostics", diagnostics_json(session.diagnostics())}};
  if (!session.loaded()) return state;
  const model::Rig& rig = session.inputs().rig;
  state["rig"] = {{"name", rig.name},
                  {"distance_m", rig.distance_of_interest},
                  {"area_top_m", rig.body.area_top()},
                  {"body_radius_m", rig.body.radius},
                  {"base_link", rig.base_link},
                  {"base_link_height_m", rig.base_link_height}};
  state["sensors"] = library_json(session.inputs().library);
  state["numbers"] = numbers_json(session, true, since);
  return state;
}

// A mesh as the page's three.js buffers want it: flat positions and indices.
json mesh_json(const model::TriangleMesh& mesh) {
  json positions = json::array();
  for (const model::Vec3& v : mesh.vertices)
    positions.insert(positions.end(), {v.x(), v.y(), v.z()});
  json indices = json::array();
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), {t[0], t[1], t[2]});
  return {{"positions", positions}, {"indices", indices}};
}

// What the mount's housing cuts into, in check's B2 words; empty: nothing.
std::string clash_text(const model::Rig& rig, const model::SensorLibrary& library,
                       std::size_t index) {
  std::string clash;
  for (const geometry::HousingClash& found : geometry::housing_clashes(rig, library, index))
    clash += (clash.empty() ? "" : "; ") + found.describe();
  return clash.empty() ? "" : rig.mounts[index].id + "'s housing " + clash + " (check: B2)";
}

// The mount's datasheet housing (robot frame) and what it cuts into, in check's B2 words
// (issue 52 item 7: the page paints a clashing housing red with the reason).
void add_housing(const model::Rig& rig, const model::SensorLibrary& library, std::size_t index,
                 json& fov) {
  const std::optional<model::BodyPart> housing =
      geometry::mount_housing(rig.mounts[index], library);
  if (!housing) return;
  fov["housing"] = mesh_json(housing->triangles);
  fov["clash"] = clash_text(rig, library, index);
}

// The moved mount's B2 verdict with every pose reply, so that a drag into the body or another
// housing turns it red while it happens (issue 52 item 7).
json moved_clash_json(const studio::StudioSession& session, const std::string& mount_id) {
  const model::Rig& rig = session.inputs().rig;
  for (std::size_t index = 0; index < rig.mounts.size(); ++index) {
    if (rig.mounts[index].id == mount_id)
      return {{"mount", mount_id}, {"text", clash_text(rig, session.inputs().library, index)}};
  }
  return nullptr;
}

json fov_json(const studio::StudioSession& session, const std::string& mount_id) {
  const model::Rig& rig = session.inputs().rig;
  for (std::size_t index = 0; index < rig.mounts.size(); ++index) {
    const model::Mount& mount = rig.mounts[index];
    if (mount.id != mount_id) continue;
    const geometry::BodyOccluder body(rig.body);
    const model::SensorMode& mode =
        session.inputs().library.resolved_mode(mount.sensor_id, mount.mode_id);
    const model::TriangleMesh mesh =
        render::visible_fov_mesh(mode, mount.T_robot_sensor, rig.distance_of_interest, body);
    json fov = mesh_json(mesh);
    fov["mount"] = mount_id;
    add_housing(rig, session.inputs().library, index, fov);
    return fov;
  }
  throw BadRequest{"no mount '" + mount_id + "'"};
}

// One cross-section as the exact path cuts it: each mount's region (rho, z) and floor pieces.
json section_json(const studio::StudioSession& session, double theta_deg) {
  if (!std::isfinite(theta_deg)) throw BadRequest{"theta_deg must be a finite number"};
  const metrics::SectionView view = metrics::section_view(
      session.inputs().rig, session.inputs().library, model::deg_to_rad(theta_deg));
  json mounts = json::array();
  for (std::size_t i = 0; i < view.mount_ids.size(); ++i) {
    json polygons = json::array();
    for (const geometry::Polygon2& polygon : view.polygons[i]) {
      json points = json::array();
      for (const model::Vec2& p : polygon) points.push_back({p.x(), p.y()});
      polygons.push_back(std::move(points));
    }
    json floor = json::array();
    for (const auto& [low, high] : view.floors[i].intervals()) floor.push_back({low, high});
    mounts.push_back({{"id", view.mount_ids[i]}, {"polygons", polygons}, {"floor", floor}});
  }
  return {{"theta_deg", theta_deg}, {"r_m", view.frame.r},       {"d_m", view.frame.d},
          {"h_m", view.frame.h},    {"complete", view.complete}, {"floor", view.floor},
          {"mounts", mounts}};
}

double query_number(const std::string& query, const std::string& key) {
  const std::optional<std::string> value = studio::query_parameter(query, key);
  if (!value || value->empty()) return 0.0;
  char* end = nullptr;
  const double number = std::strtod(value->c_str(), &end);
  if (end == value->c_str() || *end != '\0' || !std::isfinite(number) || number < 0)
    throw BadRequest{key + " must be a number >= 0"};
  return number;
}

// `rigdesign sensors`' filters over the session's library: the sensors that answer, each with
// its modes that do.
json sensors_json(const model::SensorLibrary& library, const std::string& query) {
  report::SensorQuery filter;
  filter.search = studio::query_parameter(query, "search").value_or("");
  const std::string technologies = studio::query_parameter(query, "technology").value_or("");
  for (std::size_t at = 0; at < technologies.size();) {
    const std::size_t comma = std::min(technologies.find(',', at), technologies.size());
    if (comma > at) filter.technologies.push_back(technologies.substr(at, comma - at));
    at = comma + 1;
  }
  filter.min_range = query_number(query, "min_range");
  filter.max_price = query_number(query, "max_price");
  filter.min_rate = query_number(query, "min_rate");
  filter.min_fov_deg = query_number(query, "min_fov_deg");
  json sensors = json::array();
  for (const model::Sensor& sensor : library.sensors) {
    if (!report::sensor_matches(sensor, filter)) continue;
    json modes = json::array();
    for (const model::SensorMode* mode : report::matching_modes(sensor, filter))
      modes.push_back(mode->id);
    sensors.push_back({{"id", sensor.id}, {"modes", modes}});
  }
  return {{"sensors", sensors}};
}

std::string query_value(const std::string& query, const std::string& key) {
  std::optional<std::string> value = studio::query_parameter(query, key);
  if (!value) throw BadRequest{"the query needs " + key};
  return *value;
}

}  // namespace

StudioApi::StudioApi(studio::StudioSession& session, CheckRun check)
    : session_(session), check_(std::move(check)) {}

studio::Reply StudioApi::operator()(const std::string& method, const std::string& name,
                                    const std::string& query, const std::string& body_text) {
  const std::lock_guard<std::mutex> guard(lock_);
  const auto since = std::chrono::steady_clock::now();
  try {
    if (method == "GET" && name == "state") return json_reply(state_json(session_, since));
    if (method == "POST" && name == "reload") {
      session_.reload();
      return json_reply(state_json(session_, since));
    }
    if (!session_.loaded())
      return json_reply({{"error", diagnostics_json(session_.diagnostics())}}, 409);
    if (method == "GET" && name == "scene.gltf") {
      const model::Rig& rig = session_.inputs().rig;
      return {200, "model/gltf+json",
              render::gltf_scene(rig.name, rig.base_link, rig.base_link_height,
                                 render::rig_gltf_parts(rig, session_.inputs().library))};
    }
    if (method == "GET" && name == "fov")
      return json_reply(fov_json(session_, query_value(query, "mount")));
    if (method == "GET" && name == "sensors")
      return json_reply(sensors_json(session_.inputs().library, query));
    if (method == "GET" && name == "section") {
      const std::string theta = query_value(query, "theta_deg");
      char* end = nullptr;
      const double value = std::strtod(theta.c_str(), &end);
      if (end == theta.c_str() || *end != '\0') throw BadRequest{"theta_deg must be a number"};
      return json_reply(section_json(session_, value));
    }
    if (method != "POST") return {404, "text/plain", "no such API call\n"};
    const json body = json::parse(body_text.empty() ? "{}" : body_text);
    if (!body.is_object()) throw BadRequest{"the body must be a JSON object"};
    if (name == "pose") {
      const std::string mount = text_field(body, "mount");
      session_.set_pose(mount, pose_in(body));
      json reply = numbers_json(session_, body.value("exact", false), since);
      reply["clash"] = moved_clash_json(session_, mount);
      return json_reply(reply);
    }
    if (name == "sensor") {
      session_.set_sensor(text_field(body, "mount"), text_field(body, "sensor"),
                          text_field(body, "mode"));
      return json_reply(numbers_json(session_, true, since));
    }
    if (name == "add") {
      const std::string id =
          session_.add_mount(text_field(body, "sensor"), text_field(body, "mode"), pose_in(body));
      json state = state_json(session_, since);
      state["added"] = id;
      return json_reply(state);
    }
    if (name == "remove") {
      session_.remove_mount(text_field(body, "mount"));
      return json_reply(state_json(session_, since));
    }
    if (name == "save") {
      session_.save();
      const auto [exit_code, report] = check_(session_.rig_path());
      json state = state_json(session_, since);
      state["check"] = {{"exit_code", exit_code}, {"report", report}};
      return json_reply(state);
    }
    return {404, "text/plain", "no such API call\n"};
  } catch (const model::InputError& error) {
    // The rig keeps its last valid state; the page shows check's message.
    return json_reply({{"error", diagnostics_json(error.diagnostics())}}, 422);
  } catch (const json::exception& error) {
    return json_reply(
        {{"error", std::string("the body is not the JSON expected: ") + error.what()}}, 400);
  } catch (const BadRequest& error) {
    return json_reply({{"error", error.what}}, 400);
  }
}

}  // namespace rigdesign::studio
