// SmartBody's FaceFX <curves> (docs/bml.md, "SmartBody"): not drawn (their channels are a rig's),
// but their timing is kept: the span of their keys.
#pragma once

#include <optional>
#include <utility>

#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {

// The first and last key times of the curves (seconds from the utterance's start; a key before
// 0 counts from 0), or nullopt when no key time is read or the span is empty. Each <curve>'s text
// is keys of four numbers: time, value, slope in, slope out.
std::optional<std::pair<double, double>> curves_extent(const xml::XmlDocument& doc, const xmlNode* curves);

}  // namespace fapc::bml
