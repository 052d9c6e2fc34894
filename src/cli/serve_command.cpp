// `rigdesign serve RIG [--port N] [--no-open] [--sensors FILE] [--requirements FILE]`: the
// studio (issue 37). Serves one page on loopback where the rig's mounts are moved, turned,
// swapped, added and removed by hand, with the coverage and the verdicts recomputed on every
// change, and saved back into the rig file's own text. Stops on Ctrl-C (SIGINT) or SIGTERM.
#include <pthread.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <thread>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "rigdesign/report/check_text.hpp"
#include "rigdesign/report/file_report.hpp"
#include "rigdesign/studio/launch_page.hpp"
#include "rigdesign/studio/request_guard.hpp"
#include "rigdesign/studio/studio_api.hpp"
#include "rigdesign/studio/studio_server.hpp"
#include "rigdesign/studio/studio_session.hpp"

namespace rigdesign::cli {
namespace {

struct ServeOptions {
  std::string rig;
  std::string sensors;
  std::string requirements;
  int port = 8765;
  bool no_open = false;
};

bool has_display() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && *value != '\0') return true;
  }
  return false;
}

// The browser gets the path of a page only this user can read, which sends it on to the
// tokened address: never the address itself, which every local user could read in its argv.
// The page is removed when `serve` stops.
void open_browser(const std::string& url, std::optional<studio::LaunchPage>& page,
                  std::ostream& err) {
  try {
    page.emplace(url);
  } catch (const std::runtime_error& error) {
    err << "serve: " << error.what() << "; open the address above in a browser\n";
    return;
  }
  if (!studio::start_program("xdg-open", page->path()))
    err << "serve: could not start xdg-open; open the address above in a browser\n";
}

std::pair<int, std::string> check_saved_rig(const std::string& path, const ServeOptions& options) {
  const std::vector<report::FileReport> reports = {
      report::check_file(path, options.sensors, options.requirements)};
  return {check_exit_code(reports), report::format_text(reports)};
}

int run_serve(const ServeOptions& options, std::ostream& out, std::ostream& err) {
  studio::StudioSession session(options.rig, options.sensors, options.requirements);
  if (!session.loaded()) {
    // The page shows these too; the server stays up so the file can be mended and reloaded.
    for (const model::Diagnostic& d : session.diagnostics()) err << d.message() << '\n';
  } else {
    // The first page asks for the exact numbers: computed before the address is printed, so it
    // opens at once instead of waiting behind them.
    session.numbers(true);
  }
  studio::StudioApi api(
      session, [&options](const std::string& path) { return check_saved_rig(path, options); });

  // SIGINT and SIGTERM go to one waiting thread that stops the server (blocked in every other
  // thread, the server's included, which inherit the mask).
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  sigset_t previous;
  pthread_sigmask(SIG_BLOCK, &stop_signals, &previous);
  int exit_code = kOk;
  {
    studio::StudioServer server(
        studio::new_token(), options.port,
        [&api](const std::string& method, const std::string& name, const std::string& query,
               const std::string& body) { return api(method, name, query, body); });
    out << "rigdesign studio for " << options.rig << " at\n  " << server.url() << '\n'
        << "  (loopback only" << (server.ipv6() ? ", also [::1]" : "")
        << "; saves write only that rig file; Ctrl-C stops)" << std::endl;
    std::optional<studio::LaunchPage> launch_page;
    if (!options.no_open && has_display()) open_browser(server.url(), launch_page, err);
    std::atomic<bool> signalled{false};
    std::thread watcher([&server, &stop_signals, &signalled] {
      int signal = 0;
      sigwait(&stop_signals, &signal);
      signalled = true;
      server.stop();
    });
    server.run();
    // run() returned without a signal (stop() came from elsewhere): wake the watcher with one aimed
    // at it alone, so none is left pending for the process when the mask is restored.
    if (!signalled) pthread_kill(watcher.native_handle(), SIGTERM);
    watcher.join();
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  out << "studio stopped" << (session.loaded() && session.dirty() ? " (unsaved edits dropped)" : "")
      << '\n';
  return exit_code;
}

}  // namespace

Command setup_serve(CLI::App& parent) {
  auto options = std::make_shared<ServeOptions>();
  CLI::App* app = parent.add_subcommand(
      "serve",
      "Design the rig by hand in a browser: move, turn and swap sensors and see the coverage "
      "and verdicts update (a local page on 127.0.0.1 with a token)");
  add_rig_option(*app, options->rig);
  app->add_option("--port", options->port, "Port on 127.0.0.1 and ::1 (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  app->add_flag("--no-open", options->no_open,
                "Do not open a browser (it opens when there is a display)");
  add_sensors_option(*app, options->sensors);
  add_requirements_option(*app, options->requirements);
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_serve(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
