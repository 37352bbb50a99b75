// Escaping text for the XML the program writes (junit reports, SVG plots).
#pragma once

#include <string>

namespace fapc::pipeline {

inline std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace fapc::pipeline
