// Every file the lab writes goes through here (images, stats, sidecars, bench results, logs, imgui.ini), so
// a result that cannot be stored is an error naming the file and the reason, never a success message over
// a missing or cut-off file.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace raylab {

// A write that failed; what() is "cannot write PATH: REASON" (the reason from strerror).
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Makes `path` hold exactly `bytes`, or leaves it as it was. A regular file (or a new one) is written to a
// temporary file in the same folder (mkstemp), every write checked, fsynced, closed and renamed over
// `path`: a reader never sees half of it, and a failure leaves nothing under the final name. A target that
// exists and is not a regular file (/dev/full, /dev/stdout, a FIFO) is written in place, its writes and
// close checked: renaming over it would replace the device node (and the lab may run as root). A symbolic
// link is followed, so the file it names is replaced, not the link. Throws WriteError.
void writeFileChecked(const std::string& path, std::string_view bytes);

// A file written one record at a time (the bench's results.jsonl, the window's frame log), opened with
// O_APPEND. Each append reaches the file whole or throws WriteError (and a regular file is cut back to
// where it was, so it ends on a whole record); a durable append is also fsynced, so it survives a kill or a
// power cut.
class AppendFile {
 public:
  enum class Start { Keep, Empty };  // append to what is there, or truncate first
  AppendFile(const std::string& path, Start start);  // creates the file; throws WriteError
  ~AppendFile();  // closes quietly: call close() to hear of a failure
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  void append(std::string_view bytes, bool durable);
  void close();  // throws WriteError
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace raylab
