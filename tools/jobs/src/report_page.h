#pragma once
// The frame of every report.html (`cordgrasp run`, `bench`, `merge`): the head with the error
// recorder and the style, and the tail with the 3D views' script and the self-test
// `cordgraspSelftest()` (docs/report-html.md), so that every page checks itself the same way.
#include <string>

namespace cordgrasp {

/// "<!DOCTYPE html>" up to and including "<h1>title</h1>": the error recorder (first script),
/// the style sheet, `title` (escaped) as the page's title and heading.
std::string report_page_head(const std::string& title);

/// The self-test's `<pre id="selftest">`, the script of the 3D views (every
/// `.viewer[data-model]`) and of `cordgraspSelftest()`, then "</body></html>".
std::string report_page_tail();

}  // namespace cordgrasp
