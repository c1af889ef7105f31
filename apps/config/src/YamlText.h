#pragma once
// Private to the config module: the one way it turns YAML text into nodes.
// yaml-cpp's YAML::Load keeps the first of two equal keys in a mapping
// without a word (`irf: {file: a.csv, file: b.csv}` reads a.csv), builds an
// alias as a shared node that every later walk of the document expands again
// (nested anchors, "billion laughs", expand exponentially), and builds an
// alias inside the node it names as a cycle. parseYaml first reads the
// text's events once (YAML::Parser) and refuses each of these, located, then
// loads it.

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <string>

namespace tofsim::config {

/// The most nodes that aliases may add to a document, counted as a walk of
/// it would expand them (an alias of a 10-node list counts 10). Sharing a
/// sensor's keys a few times adds tens; a nested alias bomb adds billions.
constexpr std::uint64_t kMaxAliasNodes = 1'000'000;

/// The first document of `text` as YAML::Load reads it. Throws
/// YAML::ParserException, located at the offending node (line and column
/// from 0, as yaml-cpp's marks), for a syntax error, a key given twice in one
/// mapping (the message names both places), an alias inside the node it
/// names, and aliases that expand past kMaxAliasNodes. Callers turn it into
/// an InputError in their own terms (a file, a --set value, a calibration).
YAML::Node parseYaml(const std::string& text);

}  // namespace tofsim::config
