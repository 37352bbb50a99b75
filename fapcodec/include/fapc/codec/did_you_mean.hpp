// "Did you mean": the one edit-distance ranking every suggestion uses, in the libraries (FAP and
// target names) and in the command line (subcommands, options, kinds). A suggestion only adds
// words to a message: it never changes an error's kind or a program's exit status.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fapc {

// Levenshtein distance (insertions, deletions, substitutions, each 1).
std::size_t edit_distance(std::string_view a, std::string_view b);
// The same when it is at most `bound`, else bound + 1; costs O(bound x the shorter length), and
// nothing when the lengths alone differ by more than the bound.
std::size_t bounded_edit_distance(std::string_view a, std::string_view b, std::size_t bound);

// The candidates closest to `name`, best first (ties in the candidates' order), at most
// `how_many`. With `max_distance` > 0 only those within that distance are kept; 0 keeps all
// those within the longest candidate's length of it (all of them, for a name no longer than that).
// The work is bounded by that distance times the name's length, and nothing for a candidate
// whose length alone is too far from the name's.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates,
                                       std::size_t how_many = 3, std::size_t max_distance = 0);

// A distance that still reads as a slip of the keyboard for a name this long: a third of it, at
// least 2 (two letters swapped) and at most 3; 1 for names of one or two letters ("fps" for
// "fsp", "compile" for "complie", not "info" for "mp4").
std::size_t plausible_distance(std::string_view name);

// "; did you mean a, b or c?" over the plausible closest names, or "" when none is close.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates, std::size_t how_many = 3);

// How a message quotes a name the input gave: 'name', or its first kQuotedNameLength characters
// and its length when longer ('abc...' (1000000 characters)), so that an error stays one line.
inline constexpr std::size_t kQuotedNameLength = 64;
std::string quoted_name(std::string_view name);

// "a, b or c": how suggestions are listed.
std::string or_list(const std::vector<std::string>& names);

}  // namespace fapc
