#pragma once
// A plain-text table with aligned columns, for terminal reports.
#include <iosfwd>
#include <string>
#include <vector>

namespace rigdesign::report {

class TextTable {
 public:
  enum class Align { left, right };
  void add_column(std::string header, Align align);
  void add_row(std::vector<std::string> cells);
  void print(std::ostream& out, const std::string& indent = "") const;

 private:
  std::vector<std::string> headers_;
  std::vector<Align> aligns_;
  std::vector<std::vector<std::string>> rows_;
};

/// Fixed-point text with `decimals` digits after the point.
std::string fixed(double value, int decimals);
/// fixed(), or "-" for an undefined value (NaN): a table cell.
std::string fixed_or_dash(double value, int decimals);

}  // namespace rigdesign::report
