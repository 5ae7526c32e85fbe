// Embedded files: the chunks embed_text.cmake writes come back as the file, in order.

#include <gtest/gtest.h>

#include "saltus/base/embedded_text.h"

namespace saltus {
namespace {

TEST(EmbeddedText, JoinsTheChunksInOrder) {
  const char* const chunks[] = {"first ", "second", "", " third", nullptr};
  EXPECT_EQ(embedded_text(chunks), "first second third");
  const char* const none[] = {nullptr};
  EXPECT_EQ(embedded_text(none), "");
}

}  // namespace
}  // namespace saltus
