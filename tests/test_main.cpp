#include <gtest/gtest.h>

#include "core/util/wait_policy.h"

int main(int argc, char** argv) {
  cvtmesh::prefer_passive_openmp_threads(argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
