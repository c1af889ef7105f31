#pragma once
// Private to the config module: a view of one YAML mapping that remembers which
// keys were read and reports every error with file, line, column and the full
// key path. After parsing, reportUnusedKeys() turns every key nobody read into
// an error, so a typo is never silently ignored.

#include <yaml-cpp/yaml.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::config {

class ConfigNode {
 public:
  /// The root of a document. `file` is used in every error message;
  /// `rootPath` prefixes every key path (a document inside another file: a
  /// glTF material's extras, "materials[1] 'wax'.extras").
  ConfigNode(YAML::Node node, std::string file, std::string rootPath = "");

  /// Records that the value at `keyPath` came from a command-line override, so
  /// errors under it name `source` (e.g. "--set camera.fov_y=abc") instead of
  /// a line of the file.
  void addOverrideSource(const std::string& keyPath, const std::string& source) const;

  bool has(const std::string& key) const;
  /// A child mapping/sequence/scalar. Throws a located error when missing.
  ConfigNode child(const std::string& key) const;
  std::optional<ConfigNode> optionalChild(const std::string& key) const;
  /// Elements of a sequence node.
  std::vector<ConfigNode> elements() const;
  /// The keys of a mapping node, in file order. A key that is itself a
  /// mapping or a sequence (YAML's `? [a, b]: ...`) is a located error.
  std::vector<std::string> keys() const;

  // Typed scalars. `get` returns `fallback` when the key is absent; `require`
  // throws. Wrong types throw with the location of the offending value.
  std::string getString(const std::string& key, const std::string& fallback) const;
  std::string requireString(const std::string& key) const;
  double getDouble(const std::string& key, double fallback) const;
  double requireDouble(const std::string& key) const;
  long long getInt(const std::string& key, long long fallback) const;
  bool getBool(const std::string& key, bool fallback) const;
  std::vector<double> getDoubles(const std::string& key, std::size_t count,
                                 const std::vector<double>& fallback) const;

  // Quantities with units (see Units.h). A bare number means the default unit.
  double getDuration_s(const std::string& key, double fallback_s) const;
  double getLength_m(const std::string& key, double fallback_m) const;
  double getAngle_deg(const std::string& key, double fallback_deg) const;
  double getBytes(const std::string& key, double fallback) const;
  double getFrequency_Hz(const std::string& key, double fallback_Hz) const;

  /// The value of this node itself as a scalar of the given kind.
  std::string asString() const;
  double asDouble() const;
  double asDuration_s() const;

  /// Located error for this node (or one of its keys).
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void failKey(const std::string& key, const std::string& message) const;
  FileLoc location() const;
  FileLoc locationOf(const std::string& key) const;
  const std::string& path() const { return path_; }
  /// The document's file, as given to the root (relative paths in the config
  /// resolve against its folder).
  const std::string& file() const { return shared_->file; }
  std::string pathOf(const std::string& key) const;
  const YAML::Node& yaml() const { return node_; }
  bool isMap() const { return node_.IsMap(); }
  bool isSequence() const { return node_.IsSequence(); }
  bool isScalar() const { return node_.IsScalar(); }

  /// Marks a key as read without parsing it (e.g. handled elsewhere).
  void markUsed(const std::string& key) const;
  /// Says why a key nobody read is wrong when the caller knows better than a
  /// spelling guess (a key of another sensor type); "" for no opinion. Given
  /// the key's path relative to the node reportUnusedKeys() was called on.
  using UnknownKeyHint = std::function<std::string(const std::string& relativePath)>;
  /// Throws for the first key in the whole document that no parser read,
  /// naming the closest key the parsers asked for at its level when one is a
  /// likely typo of it ("unknown key (did you mean 'camera'?)").
  void reportUnusedKeys(const UnknownKeyHint& hint = {}) const;

 private:
  struct Shared {
    std::string file;
    std::set<std::string> usedPaths;
    // Every key path a parser looked for, present or not: the known keys of
    // each level, which the typo hints choose from.
    std::set<std::string> askedPaths;
    std::vector<std::pair<std::string, std::string>> overrideSources;
  };
  FileLoc locate(const YAML::Node& node, const std::string& path) const;
  std::string keyName(const YAML::Node& key, const std::string& parentPath) const;
  ConfigNode(YAML::Node node, std::string path, std::shared_ptr<Shared> shared);
  YAML::Node lookup(const std::string& key) const;
  void collectUnused(const YAML::Node& node, const std::string& path,
                     const UnknownKeyHint& hint) const;
  std::string unknownKeyMessage(const std::string& key, const std::string& parentPath,
                                const std::string& fullPath, const UnknownKeyHint& hint) const;
  void failIfTypoOf(const std::string& missingKey) const;

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<Shared> shared_;
};

/// Loads a YAML file; syntax errors become InputError with file:line:col.
YAML::Node loadYamlFile(const std::string& path);

/// Sets the value at a dotted key path ("camera.resolution", "sensors.0.bins")
/// to `valueYaml` parsed as YAML, creating mappings on the way.
void applyOverride(YAML::Node& root, const std::string& keyPath, const std::string& valueYaml);

}  // namespace tofsim::config
