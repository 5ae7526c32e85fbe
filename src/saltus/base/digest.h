#pragma once
/// @file
/// A short digest of text: 64-bit FNV-1a as 16 hexadecimal digits. It tells texts apart that
/// differ by accident (an edited file, another study's inputs); it is not a cryptographic hash
/// and guards against no one who wants a collision.

#include <string>

namespace saltus {

/// FNV-1a (64 bits) of `text`'s bytes, as 16 lower-case hexadecimal digits.
std::string text_digest(const std::string& text);

}  // namespace saltus
