// The words and numbers FML values are written in (fml_words.cpp), for the reader's files and the
// sniffing of other formats.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fapc::fml::reading {

std::string trim(std::string_view s);
std::optional<double> number(std::string_view text);
std::string format_number(double v);
std::string lower(std::string_view s);
// Event values compare as numbers when both are ("1" and "1.0"), else as text.
bool same_value(const std::string& a, const std::string& b);
// expr types: FAP 2 expression numbers (fap_table.hpp), words of the paper and common variants.
std::optional<int> expression_number(const std::string& type);
// hdmv axes (docs/fml.md, "Moves"): 0 yaw, 1 pitch, 2 roll.
std::optional<int> head_axis(const std::string& type);

}  // namespace fapc::fml::reading
