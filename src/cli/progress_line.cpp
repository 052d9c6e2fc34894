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

std::string duration_text(double seconds) {
  if (seconds < 60) return model::format_number(std::round(seconds * 10) / 10, 3) + " s";
  const long whole = std::lround(seconds);
  return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
}

}  // namespace

ProgressLine::ProgressLine(std::ostream& err, std::string task, std::string unit)
    : err_(err), task_(std::move(task)), unit_(std::move(unit)) {
  const char* forced = std::getenv("RIGDESIGN_PROGRESS");
  if (forced != nullptr && std::string_view(forced) == "1") {
    mode_ = Mode::log;
  } else if (forced == nullptr || std::string_view(forced) != "0") {
    mode_ = ::isatty(STDERR_FILENO) == 1 ? Mode::terminal : Mode::off;
  }
  started_ = std::chrono::steady_clock::now();
  last_shown_ = started_;
}

ProgressLine::~ProgressLine() {
  clear();
}

void ProgressLine::clear() {
  if (mode_ == Mode::terminal && shown_) {
    err_ << '\r' << std::string(shown_width_, ' ') << '\r' << std::flush;
    shown_ = false;
    shown_width_ = 0;
  }
}

void ProgressLine::retitle(std::string task) {
  task_ = std::move(task);
}

void ProgressLine::begin(std::string task, std::string unit) {
  task_ = std::move(task);
  unit_ = std::move(unit);
  started_ = std::chrono::steady_clock::now();
}

std::string ProgressLine::line(const std::string& count, double share) const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
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
  // A count of whole things, though a share of the next may be done ("3/12 probes").
  show(model::format_number(std::floor(done), 10) + "/" + model::format_number(total, 10) + " " +
           unit_ + (detail.empty() ? "" : ", " + detail),
       share, done >= total);
}

void ProgressLine::update_share(double share, const std::string& detail) {
  if (mode_ == Mode::off) return;
  show(detail, share, false);
}

void ProgressLine::finish(const std::string& task, const std::string& detail, double seconds) {
  if (mode_ == Mode::off) return;
  if (!shown_ && mode_ == Mode::terminal) return;  // done before it was worth a line
  last_shown_ = std::chrono::steady_clock::now();
  write(task + ": " + detail + " (100 %), " + duration_text(seconds));
}

void ProgressLine::show(const std::string& count, double share, bool last) {
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_shown_).count();
  const double interval = mode_ == Mode::terminal ? kTerminalInterval : kLogInterval;
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
