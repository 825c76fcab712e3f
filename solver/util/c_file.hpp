// Files and folders through the C library and the system, not <fstream> and <filesystem>,
// which link the C++ library's locale machinery into every binary (docs/building.md,
// "iostreams and `std::filesystem`"). Paths are
// UTF-8 (on Windows converted to the system's UTF-16, as libstdc++'s std::filesystem does).
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace contactbody {

struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, CloseFile>;

// What a path names, without opening it (opening a FIFO with no writer blocks).
enum class PathKind { missing, regular, directory, other };
// `size` is set for a regular file; on `missing`, errno says why.
PathKind path_kind(const std::string& path, uint64_t& size);
// fopen's modes; nullptr (errno set) if it fails.
File open_file(const std::string& path, const char* mode);
// To a byte offset from the start, 64-bit on every platform; false (errno set) if it fails.
bool seek_file(std::FILE* f, uint64_t offset);
// Cuts (or extends) an open file to `size` bytes; false (errno set) if it fails.
bool resize_file(std::FILE* f, uint64_t size);
// Renames `from` to `to`, replacing `to` if it exists; false (errno set) if it fails.
bool replace_file(const std::string& from, const std::string& to);
bool remove_file(const std::string& path);
// The folder and its parents; true if it exists as a folder afterwards (else errno set).
bool create_directories(const std::string& path);
// The names of a folder's entries (without "." and ".."); empty if it cannot be read.
std::vector<std::string> directory_entries(const std::string& path);
// dir + "/" + name (no doubled separator; just name if dir is empty).
std::string join_path(const std::string& dir, const std::string& name);

}  // namespace contactbody
