#pragma once
// The studio's JSON API (issue 37): each call of the page turned into a call of the session
// and its result into JSON, in the forms `metrics --json` and `check --format json` use.
#include <functional>
#include <mutex>
#include <string>
#include <utility>

#include "rigdesign/studio/studio_server.hpp"
#include "rigdesign/studio/studio_session.hpp"

namespace rigdesign::studio {

/// Runs `check` on a rig file: its exit code and its text report.
using CheckRun = std::function<std::pair<int, std::string>(const std::string& rig_path)>;

class StudioApi {
 public:
  StudioApi(studio::StudioSession& session, CheckRun check);
  /// The router's ApiHandler: `name` is the path after /api/. Requests are served one at a
  /// time (the session is not shared between threads).
  studio::Reply operator()(const std::string& method, const std::string& name,
                           const std::string& query, const std::string& body);

 private:
  studio::StudioSession& session_;
  CheckRun check_;
  std::mutex lock_;
};

}  // namespace rigdesign::studio
