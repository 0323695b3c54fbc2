// What every page of the HTML report shares: the frame (doctype, charset, style sheet), the
// status badges, number formatting, the banner of a partial run, and the self-check that lets a
// headless browser prove a page ran clean.
//
// Self-check: the frame's first script records every uncaught error, unhandled promise
// rejection and element that fails to load (a missing image) into the page itself:
// <html data-js-errors="N"> and a visible list in #js-errors; once the page has loaded it sets
// <html data-images-loaded="L of N"> (images that loaded, of all). A page's own script ends by
// setting <html data-report-ready="1">, so a DOM dump shows both that the script ran to its end
// and that nothing went wrong. Pages load nothing from the network; they hold no external
// script, style sheet or font.
#pragma once

#include <string>
#include <string_view>

#include "conformance/framework/report/results_json.h"

namespace voxref::conf {

// From "<!doctype html>" to the opening of the page's content, inclusive: the title (escaped
// here), the style sheet, the self-check script and, for a partial run, the banner (id="partial")
// "partial report: the run was interrupted (SIGINT) ..." or, for a snapshot of a run still going
// on, "partial report: the run is still going on ...".
std::string pageHead(std::string_view title, const RunInfo& run);

// The page's own script (plain JavaScript, may be empty), the ready marker, and the closing
// tags. `script` is inserted verbatim: it must not contain "</script".
std::string pageTail(std::string_view script);

// <span class="status pass">pass</span> for a status or verdict name.
std::string badge(std::string_view statusOrVerdict);

// A figure as the report shows it: up to 9 significant digits; "—" for NaN; "∞" signs kept.
std::string htmlNumber(double v);

}  // namespace voxref::conf
