#include "YamlText.h"

#include <yaml-cpp/anchor.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <map>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace tofsim::config {

namespace {

std::string place(const YAML::Mark& mark) {
  return "line " + std::to_string(mark.line + 1) + ", column " + std::to_string(mark.column + 1);
}

// Follows the events of one document: the mappings and sequences open around
// the current node, each with the nodes it holds so far as aliases expand
// them, and each mapping with the scalar keys it has, to find a second one.
class DocumentCheck : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    closed(mark, anchor, 1, nullptr);
  }

  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string& value) override {
    if (anchor != YAML::NullAnchor) scalars_[anchor] = value;
    closed(mark, anchor, 1, &value);
  }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto size = sizes_.find(anchor);
    // yaml-cpp names anchors as they open: one that has no size yet is still open.
    if (size == sizes_.end()) {
      throw YAML::ParserException(mark, "an alias inside the node its anchor names (a cycle)");
    }
    aliasNodes_ += size->second;
    if (aliasNodes_ > kMaxAliasNodes) {
      throw YAML::ParserException(
          mark, "aliases expand this document past " + std::to_string(kMaxAliasNodes) +
                    " nodes (nested anchors and aliases; write the values out)");
    }
    const auto scalar = scalars_.find(anchor);
    closed(mark, YAML::NullAnchor, size->second,
           scalar == scalars_.end() ? nullptr : &scalar->second);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    opened(mark, anchor, false);
  }
  void OnSequenceEnd() override { close(); }

  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    opened(mark, anchor, true);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::Mark mark;
    YAML::anchor_t anchor;
    bool mapping;
    std::uint64_t nodes = 1;   ///< itself and what it holds, aliases expanded
    std::size_t children = 0;  ///< a mapping's keys and values alternate
    std::map<std::string, YAML::Mark> keys;
  };

  void opened(const YAML::Mark& mark, YAML::anchor_t anchor, bool mapping) {
    open_.push_back(Open{mark, anchor, mapping});
  }

  void close() {
    Open done = std::move(open_.back());
    open_.pop_back();
    closed(done.mark, done.anchor, done.nodes, nullptr);
  }

  // A whole node of `nodes` nodes ends inside the innermost open collection;
  // `scalar` is its text when it is a scalar (or an alias of one).
  void closed(const YAML::Mark& mark, YAML::anchor_t anchor, std::uint64_t nodes,
              const std::string* scalar) {
    if (anchor != YAML::NullAnchor) sizes_[anchor] = nodes;
    if (open_.empty()) return;
    Open& parent = open_.back();
    if (parent.mapping && parent.children % 2 == 0 && scalar != nullptr) {
      const auto [first, inserted] = parent.keys.emplace(*scalar, mark);
      if (!inserted) {
        throw YAML::ParserException(mark, "key '" + *scalar + "' appears twice in one mapping: " +
                                              place(first->second) + " and " + place(mark));
      }
    }
    ++parent.children;
    parent.nodes += nodes;
  }

  std::vector<Open> open_;
  std::unordered_map<YAML::anchor_t, std::uint64_t> sizes_;  ///< closed anchors' nodes
  std::unordered_map<YAML::anchor_t, std::string> scalars_;  ///< anchored scalars' text
  std::uint64_t aliasNodes_ = 0;
};

}  // namespace

YAML::Node parseYaml(const std::string& text) {
  std::istringstream events(text);
  YAML::Parser parser(events);
  DocumentCheck check;
  parser.HandleNextDocument(check);  // YAML::Load reads the first document alone
  return YAML::Load(text);
}

}  // namespace tofsim::config
