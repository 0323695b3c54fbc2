// junit.xml, so that CI systems show the cases: one testsuite per system, one testcase per case;
// fail -> <failure>, crash and timeout -> <error>, skip -> <skipped>, with the message.
#pragma once

#include <string>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

std::string junitXml(const std::vector<CaseResult>& results);
std::string xmlEscape(const std::string& s);

}  // namespace voxref::conf
