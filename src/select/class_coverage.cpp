#include "rigdesign/select/class_coverage.hpp"

#include <bit>
#include <stdexcept>
#include <unordered_map>

namespace rigdesign::select {
namespace {

constexpr std::size_t kClassWordBits = 64;

// A fixed pseudo-random key per option (splitmix64): a cell's signature is the sum of the
// keys of the options covering it, so equal signatures mean equal option sets except with
// probability about 2^-64 per pair, and the construction checks even that.
std::uint64_t option_key(std::uint64_t index) {
  std::uint64_t z = index * 0x9E3779B97F4A7C15ULL + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Calls visit(bit) for every set bit of `words`, offset by `base`.
template <typename Visit>
void for_each_bit(const std::vector<std::uint64_t>& words, std::size_t base, Visit visit) {
  for (std::size_t w = 0; w < words.size(); ++w) {
    for (std::uint64_t x = words[w]; x != 0; x &= x - 1) {
      visit(base + w * kClassWordBits + static_cast<std::size_t>(std::countr_zero(x)));
    }
  }
}

struct OptionRef {
  std::size_t slot;
  std::size_t option;
  const SearchOption* data;
};

}  // namespace

ClassCoverage::ClassCoverage(const SearchProblem& problem) {
  std::vector<OptionRef> options;
  option_bits_.resize(problem.slots.size());
  spans_.resize(problem.slots.size());
  for (std::size_t k = 0; k < problem.slots.size(); ++k) {
    option_bits_[k].resize(problem.slots[k].size());
    spans_[k].resize(problem.slots[k].size());
    for (std::size_t o = 0; o < problem.slots[k].size(); ++o)
      options.push_back({k, o, &problem.slots[k][o]});
  }
  const std::size_t angles = problem.grids.size();
  // Per angle: each option's class bits (empty when it covers nothing there).
  std::vector<std::vector<std::vector<std::uint64_t>>> local(
      options.size(), std::vector<std::vector<std::uint64_t>>(angles));
  begin_.assign(1, 0);
  std::vector<std::uint64_t> signature;
  std::vector<std::uint32_t> class_of;
  std::vector<std::uint32_t> members;  // per class: cells of one option inside it (the check)
  for (std::size_t a = 0; a < angles; ++a) {
    const geometry::RasterGrid& grid = problem.grids[a];
    const std::size_t cells = static_cast<std::size_t>(grid.columns) * grid.rows;
    totals_.push_back({static_cast<std::int64_t>(cells), grid.columns});
    signature.assign(cells + grid.columns, 0);
    for (std::size_t g = 0; g < options.size(); ++g) {
      const geometry::SectionRaster& raster = options[g].data->section(a);
      const std::uint64_t key = option_key(g);
      for_each_bit(raster.cell_words(), 0, [&](std::size_t bit) { signature[bit] += key; });
      for_each_bit(raster.floor_words(), cells, [&](std::size_t bit) { signature[bit] += key; });
    }
    // Classes in order of first appearance; signature 0 is "no option covers it".
    std::unordered_map<std::uint64_t, std::uint32_t> class_index;
    std::vector<std::uint32_t> cell_weight;
    std::vector<std::uint32_t> floor_weight;
    class_of.assign(signature.size(), 0);
    for (std::size_t bit = 0; bit < signature.size(); ++bit) {
      if (signature[bit] == 0) continue;
      const auto [it, added] =
          class_index.try_emplace(signature[bit], static_cast<std::uint32_t>(cell_weight.size()));
      if (added) {
        cell_weight.push_back(0);
        floor_weight.push_back(0);
      }
      class_of[bit] = it->second;
      ++(bit < cells ? cell_weight : floor_weight)[it->second];
    }
    const std::size_t classes = cell_weight.size();
    const std::size_t words = (classes + kClassWordBits - 1) / kClassWordBits;
    begin_.push_back(begin_.back() + words);
    classes_ += classes;
    cell_weight.resize(words * kClassWordBits, 0);
    floor_weight.resize(words * kClassWordBits, 0);
    cell_weight_.insert(cell_weight_.end(), cell_weight.begin(), cell_weight.end());
    floor_weight_.insert(floor_weight_.end(), floor_weight.begin(), floor_weight.end());
    for (std::size_t g = 0; g < options.size(); ++g) {
      const geometry::SectionRaster& raster = options[g].data->section(a);
      members.assign(classes, 0);
      bool any = false;
      const auto add = [&](std::size_t bit) {
        ++members[class_of[bit]];
        any = true;
      };
      for_each_bit(raster.cell_words(), 0, add);
      for_each_bit(raster.floor_words(), cells, add);
      if (!any) continue;
      std::vector<std::uint64_t>& bits = local[g][a];
      bits.assign(words, 0);
      for (std::size_t c = 0; c < classes; ++c) {
        if (members[c] == 0) continue;
        // An option covers all of a class or none of it; anything else is a key collision.
        if (members[c] != cell_weight[c] + floor_weight[c])
          throw std::logic_error("coverage classes: two option sets share a signature");
        bits[c / kClassWordBits] |= std::uint64_t{1} << (c % kClassWordBits);
      }
    }
  }
  for (std::size_t g = 0; g < options.size(); ++g) {
    std::vector<std::uint64_t>& bits = option_bits_[options[g].slot][options[g].option];
    bits.assign(words(), 0);
    for (std::size_t a = 0; a < angles; ++a) {
      if (local[g][a].empty()) continue;
      std::copy(local[g][a].begin(), local[g][a].end(),
                bits.begin() + static_cast<long>(begin_[a]));
      spans_[options[g].slot][options[g].option].push_back(static_cast<int>(a));
    }
  }
}

void ClassCoverage::add_weights(std::size_t word, std::uint64_t classes, CellCounts& counts) const {
  for (std::uint64_t x = classes; x != 0; x &= x - 1) {
    const std::size_t c = word * kClassWordBits + static_cast<std::size_t>(std::countr_zero(x));
    counts.cells += cell_weight_[c];
    counts.floor += floor_weight_[c];
  }
}

CellCounts ClassCoverage::count(std::size_t angle, const std::uint64_t* bits) const {
  CellCounts counts;
  for (std::size_t w = begin_[angle]; w < begin_[angle + 1]; ++w) {
    add_weights(w, bits[w], counts);
  }
  return counts;
}

CellCounts ClassCoverage::count_new(std::size_t angle, const std::uint64_t* bits,
                                    const std::uint64_t* known) const {
  CellCounts counts;
  for (std::size_t w = begin_[angle]; w < begin_[angle + 1]; ++w) {
    add_weights(w, bits[w] & ~known[w], counts);
  }
  return counts;
}

bool ClassCoverage::reaches(std::size_t angle, const std::uint64_t* bits,
                            const std::uint64_t* known, CellCounts have,
                            const CellCounts& need) const {
  for (std::size_t w = begin_[angle]; w < begin_[angle + 1]; ++w) {
    if (have.cells >= need.cells && have.floor >= need.floor) return true;
    add_weights(w, bits[w] & ~known[w], have);
  }
  return have.cells >= need.cells && have.floor >= need.floor;
}

CellCounts ClassCoverage::merge(std::size_t angle, const std::uint64_t* bits, std::uint64_t* words,
                                std::uint64_t* saved) const {
  CellCounts counts;
  for (std::size_t w = begin_[angle]; w < begin_[angle + 1]; ++w) {
    const std::uint64_t had = words[w];
    *saved++ = had;
    words[w] = had | bits[w];
    add_weights(w, bits[w] & ~had, counts);
  }
  return counts;
}

}  // namespace rigdesign::select
