#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace punchsweep::engine {

/// Where the engine keeps tables between runs, and whether it may: the folder, or none with
/// the reason (empty when the cache is off on purpose).
struct TableCacheFolder {
  std::optional<std::filesystem::path> folder;
  std::string not_used;  ///< why a configured folder is not used; empty otherwise
};

/// The folder where tables (the refined localizations' neighbour tables, model::ShellSums,
/// about 2 s to build per shape exponent; and every table the engine caches later) are
/// kept between runs: $PUNCHSWEEP_CACHE if set (off, 0, false, no, none or empty, in any
/// case: none; otherwise an absolute path, or none), else $XDG_CACHE_HOME/punchsweep if
/// that is absolute (the XDG rule: a relative one is ignored), else $HOME/.cache/punchsweep
/// if $HOME is absolute. No relative path is ever used: a cache in whatever folder a run
/// happens to start in would scatter files and could be anyone's.
TableCacheFolder table_cache_folder();

/// Why `folder` must not be trusted with tables, or "" if it may: like OpenSSH with key
/// files, it must be a folder (not a link to one) owned by this user (or root) and not
/// writable by group or others, since whoever can write the tables can bias every result.
/// Its key (cache_key), where there is one, must be a private file of 32 bytes of this user.
/// A folder that does not exist yet is fine (write_tables creates it, mode 0700).
std::string untrusted_folder(const std::filesystem::path& folder);

/// Makes `folder` (mode 0700, its parents as the umask says) if it does not exist, and
/// whether it may then be trusted with tables (untrusted_folder).
bool make_private_folder(const std::filesystem::path& folder);

/// The cache's key: 32 random bytes in FOLDER/key, made on first need (`create`: mode 0600,
/// linked into place so that processes making one at once agree on it). Empty where it
/// cannot be made, or where the file is not a private regular file of this user (or root)
/// of exactly 32 bytes: then no file of the cache is believed or written.
std::string cache_key(const std::filesystem::path& folder, bool create);

/// A file of the cache: "PSWTAB02", the count n (uint64), n doubles (host byte order) and
/// their HMAC-SHA-256 under the folder's key (cache_key). read_tables gives empty for a
/// missing, short, damaged or oversized file, one whose size does not match its count
/// (checked before any memory is sized by it), a symbolic link, anything but a regular file
/// (a FIFO would block), a file writable by group or others or owned by another user, and a
/// file whose signature does not verify: one not written by this engine under this key,
/// edited since (whatever checksum a forger recomputes), or of an older format. Every file
/// it gives was written by write_tables, so nothing read is solved again (the check costs
/// one hash over the file: 3 ms for the largest, s = 4's periodic tables).
std::vector<double> read_tables(const std::filesystem::path& file);
/// Written, signed, to a new file beside it (O_EXCL, O_NOFOLLOW, mode 0644) and renamed over
/// it (ranks that save the same tables at once leave one whole file); a folder or file that
/// cannot be written is skipped silently (the tables are then built again next time).
void write_tables(const std::filesystem::path& file, const std::vector<double>& tables);

/// An exclusive lock on `file` (created 0600, not followed if a link), held while alive:
/// processes that build the same cached table one after the other, the later one reading
/// what the first saved.
class FileLock {
 public:
  explicit FileLock(const std::filesystem::path& file);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace punchsweep::engine
