#pragma once
// Replacing a small text file (XDMF index, summary.json) so that a reader, or a run killed at any
// moment, only ever sees the old complete file or the new complete file: the text goes to
// "<target>.tmp", is fsync'ed, and then rename(2) swaps it in (atomic within one file system).

#include <filesystem>
#include <string_view>

namespace glossa::io {

// Throws std::runtime_error naming the file (and errno's text) if any step fails; the temporary
// file is removed in that case and the old target is left untouched.
void replaceFileAtomically(const std::filesystem::path &target, std::string_view contents);

// "<target>.tmp": where replaceFileAtomically stages the new contents.
std::filesystem::path temporaryPathFor(const std::filesystem::path &target);

} // namespace glossa::io
