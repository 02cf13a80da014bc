#include <gtest/gtest.h>
// placeholder: filled in by the level work
