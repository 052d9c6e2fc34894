#include "progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string_view>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::cli {
namespace {

constexpr double kTerminalInterval = 0.2;  // [s] fast enough to look alive, cheap to draw
constexpr double kLogInterval = 5.0;       // [s] a CI log stays readable
// How often the keep-alive thread looks whether a line is due: a fifth of the shortest
// interval it keeps, so a line is never later than that.
constexpr double kBeatsPerInterval = 5.0;

std::string duration_text(double seconds) {
  if (seconds < 60) return model::format_number(std::round(seconds * 10) / 10, 3) + " s";
  const long whole = std::lround(seconds);
  return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
}

double seconds_since(std::chrono::steady_clock::time_point then) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - then).count();
}

}  // namespace

ProgressLine::ProgressLine(std::ostream& err, std::string task, std::string unit,
                           OffTerminal off_terminal)
    : err_(err), task_(std::move(task)), unit_(std::move(unit)), log_interval_(kLogInterval) {
  const char* forced = std::getenv("RIGDESIGN_PROGRESS");
  if (forced != nullptr && std::string_view(forced) == "1") {
    mode_ = Mode::log;
  } else if (forced == nullptr || std::string_view(forced) != "0") {
    if (::isatty(STDERR_FILENO) == 1) {
      mode_ = Mode::terminal;
    } else if (off_terminal == OffTerminal::plain_lines) {
      mode_ = Mode::log;
    }
  }
  started_ = std::chrono::steady_clock::now();
  last_shown_ = started_;
}

ProgressLine::~ProgressLine() {
  if (alive_.joinable()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    alive_.join();
  }
  clear();
}

void ProgressLine::keep_alive(double interval) {
  if (mode_ == Mode::off || alive_.joinable() || !(interval > 0)) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  alive_interval_ = interval;
  log_interval_ = std::min(log_interval_, interval);
  last_shown_ = std::chrono::steady_clock::now();
  write(line(count_, share_));
  alive_ = std::thread([this] { beat(); });
}

void ProgressLine::beat() {
  const auto tick = std::chrono::duration<double>(
      std::min(alive_interval_, kTerminalInterval * kBeatsPerInterval) / kBeatsPerInterval);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, tick, [this] { return stopping_; })) {
    const double interval =
        mode_ == Mode::terminal ? std::min(alive_interval_, kTerminalInterval) : alive_interval_;
    if (paused_ || seconds_since(last_shown_) < interval) continue;
    last_shown_ = std::chrono::steady_clock::now();
    if (open_) {
      write(line(count_, share_));
    } else {  // between phases: the last one's end stays, with the time since it
      write(task_ + ": done; the next phase starts, " + duration_text(seconds_since(started_)));
    }
  }
}

void ProgressLine::clear() {
  const std::lock_guard<std::mutex> lock(mutex_);
  clear_locked();
}

void ProgressLine::clear_locked() {
  paused_ = true;  // until the next update: the command prints its report below
  if (mode_ == Mode::terminal && shown_) {
    err_ << '\r' << std::string(shown_width_, ' ') << '\r' << std::flush;
    shown_ = false;
    shown_width_ = 0;
  }
}

void ProgressLine::retitle(std::string task) {
  const std::lock_guard<std::mutex> lock(mutex_);
  task_ = std::move(task);
}

void ProgressLine::begin(std::string task, std::string unit) {
  const std::lock_guard<std::mutex> lock(mutex_);
  task_ = std::move(task);
  unit_ = std::move(unit);
  count_ = unit_.empty() ? std::string("starting") : "0 " + unit_;
  share_ = 0.0;
  open_ = true;
  paused_ = false;
  started_ = std::chrono::steady_clock::now();
}

std::string ProgressLine::line(const std::string& count, double share) const {
  const double elapsed = seconds_since(started_);
  std::string text = task_ + ": " + count + " (" +
                     std::to_string(std::lround(100 * std::clamp(share, 0.0, 1.0))) + " %), " +
                     duration_text(elapsed);
  // Work so far predicts the rest: the loops reported here do similar work per unit.
  if (share > 0.0 && share < 1.0) {
    text += ", about " + duration_text(elapsed * (1.0 - share) / share) + " left";
  }
  return text;
}

void ProgressLine::update(double done, double total, const std::string& detail) {
  const double share = total > 0 ? done / total : 1.0;
  if (mode_ == Mode::off) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  // A count of whole things, though a share of the next may be done ("3/12 probes").
  show(model::format_number(std::floor(done), 10) + "/" + model::format_number(total, 10) + " " +
           unit_ + (detail.empty() ? "" : ", " + detail),
       share, done >= total);
}

void ProgressLine::update_share(double share, const std::string& detail) {
  if (mode_ == Mode::off) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  show(detail, share, false);
}

void ProgressLine::finish(const std::string& task, const std::string& detail, double seconds) {
  if (mode_ == Mode::off) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  task_ = task;
  open_ = false;
  started_ = std::chrono::steady_clock::now();
  // Done before it was worth a line: a terminal shows nothing, unless it keeps the line alive.
  if (!shown_ && mode_ == Mode::terminal && alive_interval_ == 0.0) return;
  last_shown_ = started_;
  write(task + ": " + detail + " (100 %), " + duration_text(seconds));
}

void ProgressLine::show(const std::string& count, double share, bool last) {
  count_ = count;
  share_ = share;
  open_ = true;
  paused_ = false;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_shown_).count();
  const double interval = mode_ == Mode::terminal ? kTerminalInterval : log_interval_;
  if (!last && since < interval) return;
  if (last && !shown_ && mode_ == Mode::terminal) return;  // done before it was worth a line
  last_shown_ = now;
  write(line(count, share));
}

void ProgressLine::write(const std::string& text) {
  if (mode_ == Mode::terminal) {
    err_ << '\r' << text;
    if (text.size() < shown_width_) err_ << std::string(shown_width_ - text.size(), ' ');
    err_ << std::flush;
    shown_width_ = std::max(shown_width_, text.size());
  } else {
    err_ << text << '\n' << std::flush;
  }
  shown_ = true;
}

}  // namespace rigdesign::cli
