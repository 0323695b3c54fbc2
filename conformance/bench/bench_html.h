// index.html of `voxref bench --out DIR`: the page a person opens to read the study. It shows the
// run's driver and settings, every plot (the SVG, with links to the PNG, the gnuplot script and
// its data, and the "what each extra bit costs" line), then every table, study tables first.
// Built on the conformance report's page frame (report/html_page.h), so that the same headless
// browser check proves it loads without a script error and with every image.
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"
#include "conformance/bench/plots.h"

namespace voxref::conf {

struct PlottedFigure {
  AccuracyPlot plot;
  PlotFiles files;
};

// `header`: one paragraph of plain text (escaped here). `plotsDir`: the plots' folder relative to
// the page. `plotError`: why the plots are missing, or empty.
std::string benchHtml(const std::string& header, const std::vector<BenchTable>& tables,
                      const std::vector<PlottedFigure>& plots, const std::string& plotsDir,
                      const std::string& plotError);

}  // namespace voxref::conf
