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

// The two halves of replaceFileAtomically, for a caller that must decide between them whether
// the new contents still apply (RunReport: a stop signal's summary must not replace a newer
// one). stageFile writes `contents` to `temporary` (fsync'ed when `synced`; `renamedOnly` is
// for a write racing a kill, where the rename's atomicity is what counts, not a crash of the
// machine); publishFile renames it onto `target`. Errors name `target`; a failed half removes
// `temporary`.
enum class Durability { synced, renamedOnly };
void stageFile(const std::filesystem::path &temporary, const std::filesystem::path &target, std::string_view contents,
               Durability durability);
void publishFile(const std::filesystem::path &temporary, const std::filesystem::path &target);

// "<target>.tmp": where replaceFileAtomically stages the new contents.
std::filesystem::path temporaryPathFor(const std::filesystem::path &target);

} // namespace glossa::io
