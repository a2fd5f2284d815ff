// The invariant checks of base/check.hpp: CHECK always, DCHECK in the debug-check builds only.
#include <gtest/gtest.h>

#include "base/check.hpp"

using namespace cellproj;

TEST(Check, ABrokenInvariantIsAnInternalErrorNamingItsPlace) {
  EXPECT_NO_THROW(CELLPROJ_CHECK(1 + 1 == 2, "arithmetic"));
  try {
    CELLPROJ_CHECK(1 + 1 == 3, "arithmetic");
    FAIL();
  } catch (const InternalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("test_check.cpp:"), std::string::npos) << m;
    EXPECT_NE(m.find("arithmetic (1 + 1 == 3 does not hold)"), std::string::npos) << m;
  }
}

TEST(Check, DebugChecksRunOnlyWhereTheBuildAsksForThem) {
  int evaluated = 0;
  const auto broken = [&] { return ++evaluated < 0; };
#if defined(CELLPROJ_DCHECKS)
  EXPECT_THROW(CELLPROJ_DCHECK(broken(), "debug"), InternalError);
  EXPECT_EQ(evaluated, 1);
#else
  EXPECT_NO_THROW(CELLPROJ_DCHECK(broken(), "debug"));
  EXPECT_EQ(evaluated, 0);  // not even evaluated in release
#endif
}
