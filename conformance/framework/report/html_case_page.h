// The page of one case, cases/<id>.html (casePageName): its status (id="case-status"), message,
// description and timing; for a crash or a timeout the output its process left (id="stderr");
// every oracle's verdict, summary and figures, with the values an envelope rejected listed
// beside their allowed intervals; the effects the emulation simulated; the departures from GL
// semantics found; the rendered, emulated, reference and error-mask images side by side; the
// magnified worst pixels (html_worst_pixels.h); the case's own figures. Valid for any case,
// including one that wrote no images, ran no oracle, or crashed. Every text is escaped.
#pragma once

#include <string>

#include "conformance/framework/case.h"
#include "conformance/framework/report/results_json.h"

namespace voxref::conf {

std::string htmlCasePage(const RunInfo& run, const CaseResult& r);

}  // namespace voxref::conf
