#pragma once
// Attributes of XML start tags, read the way XML writes them, for the checks that scan a VTK XML
// file's head before VTK's reader sees it (io/vtk_xml_check.cpp, io/header_counts.cpp).
#include <optional>
#include <string>

namespace cellproj {

// The value of attribute `name` in a start tag's text (from '<' up to its '>'): name, optional
// white space, '=', optional white space, the value in double or single quotes. nullopt when absent.
std::optional<std::string> xml_attribute(const std::string& tag, const std::string& name);

// f(value) for attribute `name` of every start tag in `xml`, in order.
template <class F>
void each_xml_attribute(const std::string& xml, const std::string& name, F&& f) {
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t close = xml.find('>', at);
    if (const auto v = xml_attribute(xml.substr(at, close == std::string::npos ? std::string::npos : close - at), name))
      f(*v);
    if (close == std::string::npos) break;
  }
}

}  // namespace cellproj
