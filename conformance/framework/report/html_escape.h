// Escaping for the HTML report, and where a case's page lives. Safe on any input (untrusted
// text from a driver's stderr included): the output never opens a tag, closes an attribute or
// starts an entity of its own.
#pragma once

#include <string>
#include <string_view>

namespace voxref::conf {

// Text for an element's content or a double-quoted attribute value: & < > " ' become
// entities; control characters other than tab, newline and carriage return become spaces (they
// are not allowed in HTML); bytes that are not valid UTF-8 become U+FFFD.
std::string htmlEscape(std::string_view text);

// The page of a case, relative to the report directory: "cases/<name>.html", where <name> is the
// id with every byte outside [A-Za-z0-9._-] replaced by '_' (so it is also a safe URL path and
// never leaves cases/).
std::string casePageName(std::string_view caseId);

}  // namespace voxref::conf
