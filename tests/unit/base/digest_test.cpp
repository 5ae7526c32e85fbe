// The text digest (base/digest.h): FNV-1a 64 as published (the reference values of the FNV
// authors' test suite), and a change of one byte anywhere changes it.

#include "saltus/base/digest.h"

#include <gtest/gtest.h>

#include <string>

namespace saltus {
namespace {

TEST(TextDigest, IsFnv1a64AsPublished) {
  // http://www.isthe.com/chongo/src/fnv/test_fnv.c, FNV1A_64 of "", "a" and "foobar".
  EXPECT_EQ(text_digest(""), "cbf29ce484222325");
  EXPECT_EQ(text_digest("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(text_digest("foobar"), "85944171f73967e8");
}

TEST(TextDigest, ChangesWithAnyOneByte) {
  const std::string text = "{\"format\": \"saltus-model/1\", \"name\": \"junior\"}";
  const std::string digest = text_digest(text);
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string changed = text;
    changed[i] = static_cast<char>(changed[i] ^ 0x01);
    EXPECT_NE(text_digest(changed), digest) << i;
  }
}

}  // namespace
}  // namespace saltus
