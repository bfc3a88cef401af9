// Text put inside the XML and HTML animpak writes (the SVG frames, the animated SVG, `animpak report`'s
// page): element content and double- or single-quoted attribute values.
#pragma once

#include <string>

namespace animpak {

/// `text` with &, <, >, " and ' written as entities.
inline std::string xml_escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace animpak
