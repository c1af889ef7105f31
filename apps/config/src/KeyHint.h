#pragma once
// Private to the config module: the "did you mean" of an unknown or missing
// key. A typo is usually one or two edits (a letter dropped, doubled, swapped)
// from the key meant; a name further away is a different word and gets no
// guess, so a wrong guess never misleads.

#include <string>
#include <vector>

namespace tofsim::config {

/// Optimal string alignment distance: insertions, deletions, substitutions and
/// swaps of two neighbouring letters ("widht" -> "width") each cost 1.
std::size_t keyEditDistance(const std::string& a, const std::string& b);

/// The candidate closest to `typed` when it is close enough to be a typo of it
/// (1 edit for names up to 4 letters, 2 beyond, and fewer edits than either
/// name has letters); "" for none. Ties go to the first candidate.
std::string closestKey(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace tofsim::config
