#pragma once
/// The search's compressed view of the options' raster sections (issue 15: a search that
/// scales). At each angle, the cells (and floor columns) that exactly the same options cover
/// are merged into one class weighted by how many cells (columns) it holds. A union of
/// options is then an OR of a few words per angle and an area a weighted sum over the set
/// classes: exact (every cell keeps its class's answer) and tens of times smaller than the
/// rasters, whose cells nobody covers drop out entirely.
#include <cstdint>
#include <vector>

#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

/// Covered cells and floor columns at one angle.
struct CellCounts {
  std::int64_t cells = 0;
  std::int64_t floor = 0;
};

class ClassCoverage {
 public:
  /// Classes of every option of `problem` at each of the problem's angles.
  explicit ClassCoverage(const SearchProblem& problem);

  std::size_t angles() const { return begin_.size() - 1; }
  /// Words of a bitset over every angle's classes; angle a holds words [begin(a), end(a)).
  std::size_t words() const { return begin_.back(); }
  std::size_t begin(std::size_t angle) const { return begin_[angle]; }
  std::size_t end(std::size_t angle) const { return begin_[angle + 1]; }
  /// Classes summed over the angles (the trace reports it against the raster's cells).
  std::size_t classes() const { return classes_; }

  /// The option's bitset (words() words) and the angles at which it covers anything.
  const std::uint64_t* bits(std::size_t slot, std::size_t option) const {
    return option_bits_[slot][option].data();
  }
  const std::vector<int>& span(std::size_t slot, std::size_t option) const {
    return spans_[slot][option];
  }

  /// Cells and floor columns of the classes set in `bits` at `angle`.
  CellCounts count(std::size_t angle, const std::uint64_t* bits) const;
  /// Of the classes set in `bits` but not in `known` at `angle`.
  CellCounts count_new(std::size_t angle, const std::uint64_t* bits,
                       const std::uint64_t* known) const;
  /// Whether `have` plus the classes set in `bits` but not in `known` at `angle` reach
  /// `need` (cells and floor columns); stops counting as soon as they do.
  bool reaches(std::size_t angle, const std::uint64_t* bits, const std::uint64_t* known,
               CellCounts have, const CellCounts& need) const;
  /// Merges `bits` into `words` at `angle` (words |= bits), copying the words it had to
  /// `saved` (one per word of the angle), and returns the cells and floor columns it added:
  /// the search's step down, in one pass over the angle's words instead of three.
  CellCounts merge(std::size_t angle, const std::uint64_t* bits, std::uint64_t* words,
                   std::uint64_t* saved) const;
  /// All cells and floor columns at `angle` (the shares' denominators).
  CellCounts total(std::size_t angle) const { return totals_[angle]; }

 private:
  /// Adds the cells and floor columns of the classes set in `classes`, word `word`.
  void add_weights(std::size_t word, std::uint64_t classes, CellCounts& counts) const;

  std::vector<std::size_t> begin_;
  std::size_t classes_ = 0;
  std::vector<std::uint32_t> cell_weight_;   // per class bit (word * 64 + bit)
  std::vector<std::uint32_t> floor_weight_;  // per class bit
  std::vector<CellCounts> totals_;
  std::vector<std::vector<std::vector<std::uint64_t>>> option_bits_;
  std::vector<std::vector<std::vector<int>>> spans_;
};

}  // namespace rigdesign::select
