#include "ConfigNode.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "KeyHint.h"
#include "YamlText.h"
#include "tofsim/config/Units.h"

namespace tofsim::config {

namespace {
FileLoc locOf(const YAML::Node& node, const std::string& file) {
  const YAML::Mark mark = node.Mark();
  if (mark.line < 0) return FileLoc{file};
  return FileLoc{file, mark.line + 1, mark.column + 1};
}
}  // namespace

YAML::Node loadYamlFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(FileLoc{path}, "", "cannot open config file");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return parseYaml(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError(FileLoc{path, e.mark.line + 1, e.mark.column + 1}, "", e.msg);
  }
}

namespace {
YAML::Node parseOverrideValue(const std::string& keyPath, const std::string& valueYaml) {
  try {
    return parseYaml(valueYaml);
  } catch (const YAML::Exception& e) {
    throw InputError(FileLoc{"--set " + keyPath + "=" + valueYaml}, keyPath, e.msg);
  }
}

bool isIndex(const std::string& part) {
  return !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
}

void setAt(YAML::Node node, const std::vector<std::string>& parts, std::size_t i,
           const YAML::Node& value, const std::string& keyPath) {
  const std::string& part = parts[i];
  const bool last = i + 1 == parts.size();
  if (node.IsSequence() && isIndex(part)) {
    const std::size_t index = std::stoul(part);
    if (index >= node.size()) {
      throw InputError(
          FileLoc{"--set " + keyPath}, keyPath,
          "index " + part + " is past the end of a list of " + std::to_string(node.size()));
    }
    if (last) {
      node[index] = value;
    } else {
      setAt(node[index], parts, i + 1, value, keyPath);
    }
    return;
  }
  if (!node.IsMap() && !node.IsNull()) {
    throw InputError(FileLoc{"--set " + keyPath}, keyPath,
                     "'" + part + "' is set inside a value that is not a mapping");
  }
  if (last) {
    node[part] = value;
  } else {
    YAML::Node next = node[part];
    if (!next.IsDefined() || next.IsNull()) next = YAML::Node(YAML::NodeType::Map);
    setAt(next, parts, i + 1, value, keyPath);
    node[part] = next;
  }
}
}  // namespace

void applyOverride(YAML::Node& root, const std::string& keyPath, const std::string& valueYaml) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t dot = keyPath.find('.', begin);
    parts.push_back(keyPath.substr(begin, dot - begin));
    if (dot == std::string::npos) break;
    begin = dot + 1;
  }
  for (const std::string& part : parts) {
    if (part.empty()) throw InputError(FileLoc{"--set " + keyPath}, keyPath, "empty key in path");
  }
  setAt(root, parts, 0, parseOverrideValue(keyPath, valueYaml), keyPath);
}

ConfigNode::ConfigNode(YAML::Node node, std::string file, std::string rootPath)
    : node_(std::move(node)), path_(std::move(rootPath)), shared_(std::make_shared<Shared>()) {
  shared_->file = std::move(file);
  if (!node_.IsMap()) fail("the document must be a mapping of keys to values");
}

ConfigNode::ConfigNode(YAML::Node node, std::string path, std::shared_ptr<Shared> shared)
    : node_(std::move(node)), path_(std::move(path)), shared_(std::move(shared)) {}

std::string ConfigNode::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ConfigNode::addOverrideSource(const std::string& keyPath, const std::string& source) const {
  shared_->overrideSources.emplace_back(keyPath, source);
}

FileLoc ConfigNode::locate(const YAML::Node& node, const std::string& path) const {
  for (const auto& [prefix, source] : shared_->overrideSources) {
    const bool under =
        path == prefix ||
        (path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0 &&
         (path[prefix.size()] == '.' || path[prefix.size()] == '['));
    if (under) return FileLoc{source};
  }
  return locOf(node, shared_->file);
}

FileLoc ConfigNode::location() const { return locate(node_, path_); }

// yaml-cpp accepts any node as a mapping key; a config key is a name.
std::string ConfigNode::keyName(const YAML::Node& key, const std::string& parentPath) const {
  if (!key.IsScalar()) {
    throw InputError(locate(key, parentPath), parentPath,
                     "a key must be a plain name, not a mapping, sequence or null");
  }
  return key.Scalar();
}

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (!node_.IsMap()) return out;
  for (const auto& entry : node_) out.push_back(keyName(entry.first, path_));
  return out;
}

FileLoc ConfigNode::locationOf(const std::string& key) const {
  const YAML::Node value = lookup(key);
  return value ? locate(value, pathOf(key)) : location();
}

void ConfigNode::fail(const std::string& message) const {
  throw InputError(location(), path_, message);
}

void ConfigNode::failKey(const std::string& key, const std::string& message) const {
  throw InputError(locationOf(key), pathOf(key), message);
}

YAML::Node ConfigNode::lookup(const std::string& key) const {
  if (!node_.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  // operator[] on a const node never inserts.
  const YAML::Node& self = node_;
  return self[key];
}

bool ConfigNode::has(const std::string& key) const {
  shared_->askedPaths.insert(pathOf(key));
  const YAML::Node value = lookup(key);
  return value.IsDefined() && !value.IsNull();
}

void ConfigNode::markUsed(const std::string& key) const { shared_->usedPaths.insert(pathOf(key)); }

ConfigNode ConfigNode::child(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a mapping");
  if (!has(key)) {
    failIfTypoOf(key);
    throw InputError(location(), pathOf(key), "required key is missing");
  }
  markUsed(key);
  return ConfigNode(lookup(key), pathOf(key), shared_);
}

std::optional<ConfigNode> ConfigNode::optionalChild(const std::string& key) const {
  if (!has(key)) {
    if (lookup(key).IsDefined()) markUsed(key);  // "key:" with no value means absent
    return std::nullopt;
  }
  return child(key);
}

std::vector<ConfigNode> ConfigNode::elements() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<ConfigNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const std::string p = path_ + "[" + std::to_string(i) + "]";
    shared_->usedPaths.insert(p);
    out.push_back(ConfigNode(node_[i], p, shared_));
  }
  return out;
}

std::string ConfigNode::asString() const {
  if (!node_.IsScalar()) fail("expected a single value, not a list or mapping");
  return node_.Scalar();
}

double ConfigNode::asDouble() const {
  const std::string text = asString();
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("trailing characters");
    if (!std::isfinite(v)) fail("must be a finite number (got " + text + ")");
    return v;
  } catch (const std::logic_error&) {
    fail("expected a number (got '" + text + "')");
  }
}

double ConfigNode::asDuration_s() const {
  try {
    return parseDuration_s(asString());
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
}

std::string ConfigNode::getString(const std::string& key, const std::string& fallback) const {
  return has(key) ? child(key).asString() : (markUsed(key), fallback);
}

std::string ConfigNode::requireString(const std::string& key) const {
  return child(key).asString();
}

double ConfigNode::getDouble(const std::string& key, double fallback) const {
  return has(key) ? child(key).asDouble() : (markUsed(key), fallback);
}

double ConfigNode::requireDouble(const std::string& key) const { return child(key).asDouble(); }

long long ConfigNode::getInt(const std::string& key, long long fallback) const {
  if (!has(key)) return fallback;
  const ConfigNode c = child(key);
  const std::string text = c.asString();
  try {
    std::size_t used = 0;
    const long long v = std::stoll(text, &used);
    if (used == text.size()) return v;
  } catch (const std::logic_error&) {
  }
  // An integral float (`cycles: 1e5`, or 100000.0 from a Python dict) is that
  // integer; 2^63 bounds the conversion, which is exact for integral doubles.
  try {
    std::size_t used = 0;
    const double d = std::stod(text, &used);
    if (used == text.size() && d == std::floor(d) && std::fabs(d) < 0x1p63) {
      return static_cast<long long>(d);
    }
  } catch (const std::logic_error&) {
  }
  c.fail("expected an integer (got '" + text + "')");
}

bool ConfigNode::getBool(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const ConfigNode c = child(key);
  const std::string text = c.asString();
  if (text == "true" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "no" || text == "off") return false;
  c.fail("expected true or false (got '" + text + "')");
}

std::vector<double> ConfigNode::getDoubles(const std::string& key, std::size_t count,
                                           const std::vector<double>& fallback) const {
  if (!has(key)) return fallback;
  const ConfigNode c = child(key);
  if (!c.isSequence() || c.yaml().size() != count) {
    c.fail("expected a list of " + std::to_string(count) + " numbers");
  }
  std::vector<double> out;
  for (const ConfigNode& e : c.elements()) out.push_back(e.asDouble());
  return out;
}

namespace {
template <typename Parse>
double withUnits(const ConfigNode& node, const std::string& key, double fallback, Parse parse) {
  if (!node.has(key)) return fallback;
  const ConfigNode c = node.child(key);
  try {
    return parse(c.asString());
  } catch (const std::invalid_argument& e) {
    c.fail(e.what());
  }
}
}  // namespace

double ConfigNode::getDuration_s(const std::string& key, double fallback_s) const {
  return withUnits(*this, key, fallback_s, parseDuration_s);
}
double ConfigNode::getLength_m(const std::string& key, double fallback_m) const {
  return withUnits(*this, key, fallback_m, parseLength_m);
}
double ConfigNode::getAngle_deg(const std::string& key, double fallback_deg) const {
  return withUnits(*this, key, fallback_deg, parseAngle_deg);
}
double ConfigNode::getBytes(const std::string& key, double fallback) const {
  return withUnits(*this, key, fallback, parseBytes);
}
double ConfigNode::getFrequency_Hz(const std::string& key, double fallback_Hz) const {
  return withUnits(*this, key, fallback_Hz, parseFrequency_Hz);
}

// A required key is missing: when a key beside it that no parser knows is one
// typo away, that typo is the error to report ("camra" for "camera"), not the
// absence.
void ConfigNode::failIfTypoOf(const std::string& missingKey) const {
  if (!node_.IsMap()) return;
  std::vector<std::string> strangers;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) continue;
    const std::string p = pathOf(entry.first.Scalar());
    if (!shared_->usedPaths.count(p) && !shared_->askedPaths.count(p)) {
      strangers.push_back(entry.first.Scalar());
    }
  }
  const std::string typo = closestKey(missingKey, strangers);
  if (typo.empty()) return;
  for (const auto& entry : node_) {
    if (entry.first.IsScalar() && entry.first.Scalar() == typo) {
      throw InputError(locate(entry.first, pathOf(typo)), pathOf(typo),
                       "unknown key (did you mean '" + missingKey + "'?)");
    }
  }
}

std::string ConfigNode::unknownKeyMessage(const std::string& key, const std::string& parentPath,
                                          const std::string& fullPath,
                                          const UnknownKeyHint& hint) const {
  if (hint) {
    const std::string relative =
        path_.empty() ? fullPath : fullPath.substr(std::min(fullPath.size(), path_.size() + 1));
    const std::string why = hint(relative);
    if (!why.empty()) return "unknown key: " + why;
  }
  // The keys the parsers looked for at this level.
  const std::string prefix = parentPath.empty() ? "" : parentPath + ".";
  std::vector<std::string> known;
  for (const std::set<std::string>* paths : {&shared_->askedPaths, &shared_->usedPaths}) {
    for (const std::string& p : *paths) {
      if (p.size() <= prefix.size() || p.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string rest = p.substr(prefix.size());
      if (rest.find_first_of(".[") == std::string::npos) known.push_back(rest);
    }
  }
  const std::string guess = closestKey(key, known);
  return guess.empty() ? "unknown key" : "unknown key (did you mean '" + guess + "'?)";
}

void ConfigNode::collectUnused(const YAML::Node& node, const std::string& path,
                               const UnknownKeyHint& hint) const {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      collectUnused(node[i], path + "[" + std::to_string(i) + "]", hint);
    }
    return;
  }
  if (!node.IsMap()) return;
  for (const auto& entry : node) {
    const std::string key = keyName(entry.first, path);
    const std::string p = path.empty() ? key : path + "." + key;
    if (!shared_->usedPaths.count(p)) {
      throw InputError(locate(entry.first, p), p, unknownKeyMessage(key, path, p, hint));
    }
    collectUnused(entry.second, p, hint);
  }
}

void ConfigNode::reportUnusedKeys(const UnknownKeyHint& hint) const {
  collectUnused(node_, path_, hint);
}

}  // namespace tofsim::config
