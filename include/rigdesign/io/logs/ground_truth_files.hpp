#pragma once
/// Reads and writes the ground-truth files the KPIs compare against
/// (rigdesign/localize/ground_truth.hpp).
#include <string>
#include <vector>

#include "rigdesign/localize/ground_truth.hpp"

namespace rigdesign::io {

/// CSV with header `bssid,x,y,z` (columns in any order), one emitter per line. Errors name
/// file:line:column like the log readers.
std::vector<localize::EmitterTruth> parse_emitter_truth(const std::string& text,
                                                        const std::string& file);

std::vector<localize::EmitterTruth> read_emitter_truth(const std::string& path);

std::string to_emitter_truth_csv(const std::vector<localize::EmitterTruth>& truth);

/// Reads the artifact list (JSON, read with the YAML parser, which accepts it); InputError
/// naming line and column on a missing or mistyped key.
std::vector<localize::Artifact> read_artifacts(const std::string& path);

}  // namespace rigdesign::io
