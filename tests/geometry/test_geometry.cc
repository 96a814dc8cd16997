// placeholder
#include <gtest/gtest.h>
TEST(Geometry, Placeholder) {}
