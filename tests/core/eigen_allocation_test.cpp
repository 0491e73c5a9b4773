// Eigen takes malloc's blocks to be 16-byte aligned (EIGEN_MALLOC_ALREADY_ALIGNED=1, glibc's way,
// also in the sanitizer build, where the top CMakeLists.txt says why): the allocator of every
// build, ASan's included, must give such blocks, or Eigen's aligned loads fault.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

namespace ballsight {
namespace {

bool aligned16(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % 16 == 0;
}

TEST(EigenAllocation, MallocAndNewGiveSixteenByteAlignedBlocks) {
  ASSERT_EQ(EIGEN_MALLOC_ALREADY_ALIGNED, 1);
  int misaligned = 0;
  for (std::size_t size = 1; size <= 4096; size += size < 64 ? 1 : 13) {
    const std::unique_ptr<void, decltype(&std::free)> block(std::malloc(size), &std::free);
    const std::unique_ptr<char[]> array(new char[size]);
    misaligned += !aligned16(block.get()) + !aligned16(array.get());
  }
  EXPECT_EQ(misaligned, 0);
}

TEST(EigenAllocation, DynamicMatricesAreAligned) {
  std::vector<Eigen::VectorXd> vectors;
  for (Eigen::Index n = 1; n < 200; ++n) vectors.emplace_back(Eigen::VectorXd::Constant(n, 1.0));
  for (const Eigen::VectorXd& v : vectors) EXPECT_TRUE(aligned16(v.data())) << v.size();
}

}  // namespace
}  // namespace ballsight
