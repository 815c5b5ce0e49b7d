// A fingerprint of a folder's contents (relative names and bytes of its regular files, sorted),
// so a rerun can tell a hand-in that changed from one that did not. FNV-1a, 64 bits: a change
// detector, not a security measure.
#pragma once

#include <string>

namespace sl {

// 16 hex digits of FNV-1a over `bytes`, continuing from `seed` (a previous value).
std::string fnv1aHex(const std::string& bytes);
unsigned long long fnv1a(const std::string& bytes, unsigned long long seed = 14695981039346656037ull);

// The fingerprint of the regular files under `root` (links and other kinds are skipped, never
// followed). "" when `root` is not a folder.
std::string contentHash(const std::string& root);

}  // namespace sl
