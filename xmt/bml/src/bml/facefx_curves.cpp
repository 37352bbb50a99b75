#include "bml/facefx_curves.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "bml/sync_ref.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::bml {

std::optional<std::pair<double, double>> curves_extent(const xml::XmlDocument& doc, const xmlNode* curves) {
  std::optional<double> first;
  std::optional<double> last;
  for (const xmlNode* curve : doc.children(curves)) {
    if (xml::local_name(curve) != "curve") continue;
    std::istringstream numbers(xml::text_content(curve));
    std::string token;
    for (std::size_t i = 0; numbers >> token; ++i) {
      if (i % 4 != 0) continue;  // value, slope in, slope out
      const auto time = parse_seconds(token);
      if (!time) continue;
      first = std::min(first.value_or(*time), *time);
      last = std::max(last.value_or(*time), *time);
    }
  }
  if (!first || !last) return std::nullopt;
  const double start = std::max(0.0, *first);
  if (!(*last > start)) return std::nullopt;
  return std::make_pair(start, *last);
}

}  // namespace fapc::bml
