#pragma once
// study/ is the front ends' single entry point (cli/, python/): they translate arguments, call one
// study/ function per use case and print what it returns, and include study/ and common/ alone
// (tests/layering_test.cpp). Beside those calls they need the study file itself: Study, its
// assemblies and scenarios, and loadStudy (io/study.hpp), which this header gives them.
#include <vector>

#include "io/study.hpp"

namespace dtwin {

/// A time window as a front end gives it, T0,T1 [s], into `begin_s` and `end_s`: left as they are
/// when `window` is empty; InputError naming --window unless it holds two numbers with T0 < T1.
void applyTimeWindow(const std::vector<double>& window, double& begin_s, double& end_s);

}  // namespace dtwin
