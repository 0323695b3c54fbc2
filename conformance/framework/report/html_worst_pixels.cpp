#include "conformance/framework/report/html_worst_pixels.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_page.h"

namespace voxref::conf {
namespace {

constexpr int kRadius = 5;  // 11 x 11 pixels
constexpr int kZoom = 8;    // matches .crop in html_page.cpp

std::string crop(const std::string& src, const std::string& caption, int x, int y) {
  std::ostringstream h;
  h << "<figure class=\"crop-figure\" style=\"display:inline-block;margin:0 4px 0 0\"><div class=\"crop\"><img src=\""
    << htmlEscape(src) << "\" alt=\"" << htmlEscape(caption)
    << " around the pixel\" style=\"left:" << -(x - kRadius) * kZoom << "px;bottom:" << -(y - kRadius) * kZoom
    << "px\"><span class=\"centre\"></span></div><figcaption class=\"crop-caption\">" << htmlEscape(caption)
    << "</figcaption></figure>";
  return h.str();
}

std::string difference(double a, double b) { return std::isnan(a) || std::isnan(b) ? "—" : htmlNumber(a - b); }

}  // namespace

std::string worstPixelsSection(const CaseResult& r, const std::string& toRoot) {
  std::ostringstream h;
  h << "<section id=\"worst-pixels\"><h2>Worst pixels, magnified</h2>\n";
  if (r.worstPixels.empty()) {
    h << "<p>The case singled out no pixel.</p></section>\n";
    return h.str();
  }
  const std::pair<const std::string*, const char*> images[] = {{&r.images.rendered, "GL"},
                                                               {&r.images.emulated, "emulated"},
                                                               {&r.images.reference, "reference"},
                                                               {&r.images.errorMask, "error mask"}};
  bool anyImage = false;
  for (const auto& [path, caption] : images) anyImage = anyImage || !path->empty();
  h << "<p>Worst first. (x, y) is the pixel with row 0 at the bottom as GL reads back; k the plane or frame. Values "
       "are those the case "
       "compares, in its units."
    << (anyImage ? " Crops: 11 × 11 pixels enlarged 8 times, the pixel outlined."
                 : " The case wrote no images, so there are no crops.")
    << "</p>\n<table id=\"worst-pixel-table\"><thead><tr><th>#</th><th>x, y, "
       "k</th><th>oracle</th><th>GL</th><th>emulated</th><th>reference</th>"
       "<th>GL − emulated</th><th>GL − reference</th><th>allowed</th>"
    << (anyImage ? "<th>crops</th>" : "") << "</tr></thead><tbody>\n";
  int n = 0;
  for (const PixelValues& p : r.worstPixels) {
    h << "<tr class=\"worst-pixel\" data-x=\"" << p.x << "\" data-y=\"" << p.y << "\" data-k=\"" << p.k
      << "\"><td class=\"num\">" << ++n << "</td><td class=\"num\">" << p.x << ", " << p.y << ", " << p.k << "</td><td>"
      << htmlEscape(p.oracle) << "</td><td class=\"num\">" << htmlNumber(p.gl) << "</td><td class=\"num\">"
      << htmlNumber(p.emulated) << "</td><td class=\"num\">" << htmlNumber(p.reference) << "</td><td class=\"num\">"
      << difference(p.gl, p.emulated) << "</td><td class=\"num\">" << difference(p.gl, p.reference) << "</td><td>";
    if (p.allowed) {
      const bool inside = p.gl >= p.allowed->first && p.gl <= p.allowed->second;
      h << "[" << htmlNumber(p.allowed->first) << ", " << htmlNumber(p.allowed->second) << "] "
        << (std::isnan(p.gl) ? ""
            : inside         ? "<span class=\"status pass\">GL inside</span>"
                             : "<span class=\"status fail\">GL outside</span>");
    } else {
      h << "—";
    }
    h << "</td>";
    if (anyImage) {
      h << "<td class=\"crops\">";
      for (const auto& [path, caption] : images)
        if (!path->empty()) h << crop(toRoot + *path, caption, p.x, p.y);
      h << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</tbody></table></section>\n";
  return h.str();
}

}  // namespace voxref::conf
