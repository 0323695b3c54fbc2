#include "conformance/framework/report/html_page.h"

#include <cmath>
#include <cstdio>

#include "conformance/framework/report/html_escape.h"

namespace voxref::conf {
namespace {

const char* kStyle = R"css(
body { font: 14px/1.4 system-ui, sans-serif; margin: 2em; color: #222; }
h1 { font-size: 1.6em; } h2 { margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.5em 0; } td, th { border: 1px solid #ddd; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f4f4f4; } .num { text-align: right; font-variant-numeric: tabular-nums; }
.status { font-weight: bold; padding: 1px 6px; border-radius: 3px; color: #fff; white-space: nowrap; }
.pass { background: #2a8a3a; } .warn { background: #c79100; } .fail { background: #c62828; }
.skip { background: #777; } .crash, .timeout { background: #6a1b9a; } .not_run { background: #999; } .info { background: #1565c0; }
.partial { background: #fff3cd; border: 2px solid #c79100; padding: 0.5em 1em; font-size: 1.2em; font-weight: bold; }
.js-error-box { background: #fde0e0; border: 2px solid #c62828; padding: 0.5em 1em; }
.filters { background: #f8f8f8; padding: 0.5em 1em; border: 1px solid #ddd; } .filters label { margin-right: 1em; }
.images figure { display: inline-block; margin: 0 1em 1em 0; vertical-align: top; }
.images figure img { width: 256px; image-rendering: pixelated; border: 1px solid #ccc; }
.crop { position: relative; display: inline-block; overflow: hidden; width: 88px; height: 88px; border: 1px solid #999; background: #000; margin: 0 4px 0 0; }
.crop img { position: absolute; max-width: none; transform: scale(8); transform-origin: 0 100%; image-rendering: pixelated; }
.crop .centre { position: absolute; left: 40px; bottom: 40px; width: 8px; height: 8px; outline: 2px solid #0ff; }
.crop-caption { font-size: 0.8em; color: #555; text-align: center; }
.crops { white-space: nowrap; }
pre { background: #f8f8f8; padding: 0.5em; overflow-x: auto; max-height: 32em; }
.message { max-width: 40em; overflow-wrap: anywhere; } code { overflow-wrap: anywhere; }
details { margin: 0.3em 0; } summary { cursor: pointer; }
)css";

// Runs before anything else on the page (see html_page.h, "Self-check").
const char* kSelfCheck = R"js(
(function () {
  var errors = [], shown = 0;
  function flush() {
    var list = document.getElementById('js-errors');
    if (!list) return;
    for (; shown < errors.length; ++shown) {
      var item = document.createElement('li');
      item.textContent = errors[shown];
      list.appendChild(item);
    }
    list.parentNode.hidden = errors.length === 0;
  }
  function note(text) {
    errors.push(text);
    document.documentElement.setAttribute('data-js-errors', String(errors.length));
    flush();
  }
  window.addEventListener('error', function (e) {
    var t = e.target;
    if (t && t !== window && t.tagName) note('could not load ' + t.tagName.toLowerCase() + ' ' + (t.currentSrc || t.src || t.href || ''));
    else note('uncaught error: ' + e.message + ' (' + e.filename + ':' + e.lineno + ')');
  }, true);
  window.addEventListener('unhandledrejection', function (e) { note('unhandled promise rejection: ' + e.reason); });
  document.addEventListener('DOMContentLoaded', flush);
  window.addEventListener('load', function () {
    var images = Array.prototype.slice.call(document.images);
    var loaded = images.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
    document.documentElement.setAttribute('data-images-loaded', loaded + ' of ' + images.length);
  });
})();
)js";

}  // namespace

std::string pageHead(std::string_view title, const RunInfo& run) {
  std::string h = "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" + htmlEscape(title) +
                  "</title>\n<link rel=\"icon\" href=\"data:,\">\n<style>" + kStyle + "</style>\n<script>" +
                  kSelfCheck +
                  "</script>\n</head><body>\n"
                  "<div class=\"js-error-box\" hidden><p>This page hit errors in the browser:</p><ul "
                  "id=\"js-errors\"></ul></div>\n";
  if (!run.complete) {
    h += "<p class=\"partial\" id=\"partial\">partial report: ";
    if (run.running)
      h += "the run is still going on; this snapshot holds the cases that finished so far.";
    else
      h += "the run was interrupted" +
           (run.interruptedBy.empty() ? std::string() : " (" + htmlEscape(run.interruptedBy) + ")") +
           "; it holds only the cases that finished" +
           (run.notRun.empty() ? std::string(".")
                               : "; " + std::to_string(run.notRun.size()) + " selected case(s) did not run.");
    h += "</p>\n";
  }
  return h;
}

std::string pageTail(std::string_view script) {
  return "<script>\n(function () {\n" + std::string(script) +
         "\n})();\ndocument.documentElement.setAttribute('data-report-ready', '1');\n</script>\n</body></html>\n";
}

std::string badge(std::string_view s) {
  const std::string e = htmlEscape(s);
  return "<span class=\"status " + e + "\">" + e + "</span>";
}

std::string htmlNumber(double v) {
  if (std::isnan(v)) return "—";
  if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace voxref::conf
