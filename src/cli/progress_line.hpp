#pragma once
// A progress line on standard error for subcommands that can run longer than two seconds:
// "occupancy: 41/160 frames (26 %), 12 s, about 35 s left". On a terminal it rewrites one line
// and erases it when done; elsewhere it is silent, unless RIGDESIGN_PROGRESS=1 asks for a
// plain line every few seconds (CI logs). Standard output stays the report alone.
#include <chrono>
#include <iosfwd>
#include <string>

namespace rigdesign::cli {

class ProgressLine {
 public:
  /// `task` leads the line; `unit` names what is counted ("frames", "runs").
  ProgressLine(std::ostream& err, std::string task, std::string unit);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();

  /// Shown at most every 0.2 s on a terminal, 5 s otherwise, and always at the end.
  void update(double done, double total, const std::string& detail = "");
  /// For work known only as a share (a search tree's estimated fraction): `detail` stands in
  /// for the count ("5,021 nodes").
  void update_share(double share, const std::string& detail);
  /// A new stage with its own count, same line ("search of relaxation step 2/4").
  void retitle(std::string task);
  /// A new phase: its own title and unit, and its own clock, so the time left is estimated
  /// from this phase's rate alone.
  void begin(std::string task, std::string unit);
  /// The phase `task` ended after `seconds`, having done `detail`: its last line.
  void finish(const std::string& task, const std::string& detail, double seconds);
  /// Erases the line on a terminal, before the command prints to standard output.
  void clear();
  bool enabled() const { return mode_ != Mode::off; }

 private:
  enum class Mode { off, terminal, log };
  std::string line(const std::string& count, double share) const;
  void show(const std::string& count, double share, bool last);
  void write(const std::string& text);

  std::ostream& err_;
  std::string task_;
  std::string unit_;
  Mode mode_ = Mode::off;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point last_shown_;
  std::size_t shown_width_ = 0;
  bool shown_ = false;
};

}  // namespace rigdesign::cli
