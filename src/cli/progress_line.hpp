#pragma once
// A progress line on standard error for subcommands that can run longer than two seconds:
// "occupancy: 41/160 frames (26 %), 12 s, about 35 s left". On a terminal it rewrites one line
// and erases it when done; elsewhere it is silent, unless RIGDESIGN_PROGRESS=1 asks for a
// plain line every few seconds (CI logs), or the command asks for plain lines by default
// (select, issue 55). Standard output stays the report alone.
#include <chrono>
#include <condition_variable>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>

namespace rigdesign::cli {

class ProgressLine {
 public:
  /// What the line does where standard error is no terminal and RIGDESIGN_PROGRESS is unset.
  enum class OffTerminal { silent, plain_lines };

  /// `task` leads the line; `unit` names what is counted ("frames", "runs").
  ProgressLine(std::ostream& err, std::string task, std::string unit,
               OffTerminal off_terminal = OffTerminal::silent);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();

  /// Shows the line now and then at least every `interval` seconds from a background thread
  /// until the line is destroyed, with the elapsed time and time left brought up to date: a
  /// phase that reports rarely (one long step, a count of a few large units) still shows that
  /// it runs. Plain lines come every `interval` seconds, not every 5.
  void keep_alive(double interval);
  /// Shown at most every 0.2 s on a terminal, 5 s otherwise, and always at the end.
  /// Safe to call from any thread.
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
  /// Erases the line on a terminal, before the command prints to standard output; the
  /// keep-alive thread waits for the next update or phase before it shows a line again.
  void clear();
  bool enabled() const { return mode_ != Mode::off; }

 private:
  enum class Mode { off, terminal, log };
  std::string line(const std::string& count, double share) const;
  void show(const std::string& count, double share, bool last);
  void write(const std::string& text);
  void clear_locked();
  void beat();  // the keep-alive thread

  std::ostream& err_;
  std::string task_;
  std::string unit_;
  Mode mode_ = Mode::off;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point last_shown_;
  std::size_t shown_width_ = 0;
  bool shown_ = false;
  // The last state shown or asked for, so the keep-alive thread can show it again; `open_`
  // is false between a phase's end and the next phase's start.
  std::string count_ = "starting";
  double share_ = 0.0;
  bool open_ = true;
  bool paused_ = false;  // cleared for the report: shown again at the next update
  double log_interval_;
  double alive_interval_ = 0.0;  // 0: no keep-alive thread
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread alive_;
};

}  // namespace rigdesign::cli
