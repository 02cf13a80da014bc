// HTML escaping, shared by the suite report's pages and pictures and the 3D replay page: one
// rule for every piece of text that goes into HTML text or an attribute.
#pragma once

#include <string>

namespace sightline::experiments {

// Escapes &, <, >, " and ' for HTML text and (either kind of quoted) attributes.
std::string html_escape(const std::string& text);

}  // namespace sightline::experiments
