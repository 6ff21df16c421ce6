// Flag values that name files and directories the command will write (cloudsvc --out,
// --out-dir, serve --listen unix:PATH; sim_client --out, --contact-sheet, --json). Each
// check throws FlagError (option_values.h) naming the flag; none creates anything: the
// command does that later, after every flag was accepted.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace cloudsvc::cli {

// `dir` (where a file or sub-directory will be created) exists, is a directory and is
// writable; otherwise FlagError for `flag value`.
void require_writable_directory(std::string_view flag, const std::string& value, const std::filesystem::path& dir);

// A file that can be created or replaced: its directory is writable
// (require_writable_directory; "." for a bare name), the path is not a directory, and an
// existing file there is writable. The file itself is not created.
void check_writable_file(std::string_view flag, const std::string& path);

// FILE.png or FILE.exr (any case) that check_writable_file accepts.
void check_output_file(std::string_view flag, const std::string& path);

// An existing writable directory, or an absent one whose nearest existing ancestor is a
// writable directory (the command creates it later, not the parser).
void check_output_directory(std::string_view flag, const std::string& dir_text);

}  // namespace cloudsvc::cli
