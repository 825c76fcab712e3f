#include "util/c_file.hpp"

#include <cerrno>

#ifdef _WIN32
#include <direct.h>
#include <io.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <windows.h>
#else
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace contactbody {

#ifdef _WIN32
namespace {

std::wstring wide(const std::string& utf8) {
    if (utf8.empty()) return {};
    const int n = MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), nullptr, 0);
    std::wstring out(static_cast<size_t>(n), L'\0');
    MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), out.data(), n);
    return out;
}

std::string utf8(const wchar_t* w) {
    const int n = WideCharToMultiByte(CP_UTF8, 0, w, -1, nullptr, 0, nullptr, nullptr);
    std::string out(static_cast<size_t>(n > 0 ? n - 1 : 0), '\0');
    if (n > 1) WideCharToMultiByte(CP_UTF8, 0, w, -1, out.data(), n, nullptr, nullptr);
    return out;
}

bool is_directory(const std::wstring& path) {
    const DWORD a = GetFileAttributesW(path.c_str());
    return a != INVALID_FILE_ATTRIBUTES && (a & FILE_ATTRIBUTE_DIRECTORY);
}

}  // namespace

PathKind path_kind(const std::string& path, uint64_t& size) {
    struct _stat64 s;
    if (_wstat64(wide(path).c_str(), &s) != 0) return PathKind::missing;
    size = static_cast<uint64_t>(s.st_size);
    return (s.st_mode & _S_IFMT) == _S_IFREG   ? PathKind::regular
           : (s.st_mode & _S_IFMT) == _S_IFDIR ? PathKind::directory
                                               : PathKind::other;
}
File open_file(const std::string& path, const char* mode) {
    return File(_wfopen(wide(path).c_str(), wide(mode).c_str()));
}
bool seek_file(std::FILE* f, uint64_t offset) {
    return _fseeki64(f, static_cast<long long>(offset), SEEK_SET) == 0;
}
bool resize_file(std::FILE* f, uint64_t size) {
    return std::fflush(f) == 0 && _chsize_s(_fileno(f), static_cast<long long>(size)) == 0;
}
bool replace_file(const std::string& from, const std::string& to) {
    if (MoveFileExW(wide(from).c_str(), wide(to).c_str(), MOVEFILE_REPLACE_EXISTING)) return true;
    errno = EACCES;
    return false;
}
bool remove_file(const std::string& path) { return _wremove(wide(path).c_str()) == 0; }
bool create_directories(const std::string& path) {
    const std::wstring w = wide(path);
    int error = 0;
    for (size_t at = 0; at != std::wstring::npos;) {
        at = w.find_first_of(L"/\\", at + 1);
        const std::wstring part = w.substr(0, at);
        if (!part.empty() && !is_directory(part) && _wmkdir(part.c_str()) != 0 && errno != EEXIST)
            error = errno;
    }
    if (is_directory(w)) return true;
    errno = error ? error : ENOTDIR;
    return false;
}
std::vector<std::string> directory_entries(const std::string& path) {
    std::vector<std::string> names;
    WIN32_FIND_DATAW entry;
    const HANDLE h = FindFirstFileW(wide(join_path(path, "*")).c_str(), &entry);
    if (h == INVALID_HANDLE_VALUE) return names;
    do {
        const std::string name = utf8(entry.cFileName);
        if (name != "." && name != "..") names.push_back(name);
    } while (FindNextFileW(h, &entry));
    FindClose(h);
    return names;
}
#else
PathKind path_kind(const std::string& path, uint64_t& size) {
    struct stat s;
    if (stat(path.c_str(), &s) != 0) return PathKind::missing;
    size = static_cast<uint64_t>(s.st_size);
    return S_ISREG(s.st_mode)   ? PathKind::regular
           : S_ISDIR(s.st_mode) ? PathKind::directory
                                : PathKind::other;
}
File open_file(const std::string& path, const char* mode) { return File(std::fopen(path.c_str(), mode)); }
bool seek_file(std::FILE* f, uint64_t offset) { return fseeko(f, static_cast<off_t>(offset), SEEK_SET) == 0; }
bool resize_file(std::FILE* f, uint64_t size) {
    return std::fflush(f) == 0 && ftruncate(fileno(f), static_cast<off_t>(size)) == 0;
}
bool replace_file(const std::string& from, const std::string& to) {
    return std::rename(from.c_str(), to.c_str()) == 0;
}
bool remove_file(const std::string& path) { return std::remove(path.c_str()) == 0; }
bool create_directories(const std::string& path) {
    struct stat s;
    int error = 0;
    for (size_t at = 0; at != std::string::npos;) {
        at = path.find('/', at + 1);
        const std::string part = path.substr(0, at);
        if (!part.empty() && stat(part.c_str(), &s) != 0 && mkdir(part.c_str(), 0777) != 0 && errno != EEXIST)
            error = errno;
    }
    if (stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode)) return true;
    errno = error ? error : ENOTDIR;
    return false;
}
std::vector<std::string> directory_entries(const std::string& path) {
    std::vector<std::string> names;
    DIR* dir = opendir(path.c_str());
    if (!dir) return names;
    while (const dirent* entry = readdir(dir)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..") names.push_back(name);
    }
    closedir(dir);
    return names;
}
#endif

std::string join_path(const std::string& dir, const std::string& name) {
    if (dir.empty()) return name;
    const char last = dir.back();
    return last == '/' || last == '\\' ? dir + name : dir + "/" + name;
}

}  // namespace contactbody
