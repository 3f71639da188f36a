// arnoldweb: error types. Every failure the library reports is one of these;
// each carries what a user needs to fix it (file/line/column/key, the API call
// and its status, the full build log and options).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace arnoldweb {

// Text a user gave (a path, a --set or --device value), fit to be echoed in a
// message: control characters written as escapes (\n, \t, \u001b), bytes
// that are not UTF-8 as \xHH; everything else as it is.
std::string printable(const std::string& text);

// Base of all library errors. exit_code() is what the CLI returns for it.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
  virtual int exit_code() const noexcept { return 1; }
};

// A scene that cannot be run as written: unreadable file, TOML syntax, unknown
// key, wrong type, value out of range. line/column are 1-based, 0 if unknown.
class SceneError : public Error {
 public:
  SceneError(std::string file, int line, int column, std::string key, std::string message);
  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  int column() const noexcept { return column_; }
  const std::string& key() const noexcept { return key_; }
  const std::string& message() const noexcept { return message_; }
  int exit_code() const noexcept override { return 2; }

 private:
  std::string file_, key_, message_;
  int line_, column_;
};

// A device that is missing, lacks a capability, runs out of memory, or an API
// call that failed. `call` names the API function, `status` its return code.
class DeviceError : public Error {
 public:
  DeviceError(std::string device, std::string call, long status, std::string message);
  const std::string& device() const noexcept { return device_; }
  const std::string& call() const noexcept { return call_; }
  long status() const noexcept { return status_; }
  int exit_code() const noexcept override { return 4; }

 private:
  std::string device_, call_;
  long status_;
};

// A kernel program that failed to compile: the full log and the options used.
class BuildError : public Error {
 public:
  BuildError(std::string device, std::string options, std::string log);
  const std::string& options() const noexcept { return options_; }
  const std::string& log() const noexcept { return log_; }
  int exit_code() const noexcept override { return 4; }

 private:
  std::string options_, log_;
};

// An output that cannot be written (exists, no permission, disk full).
class OutputError : public Error {
 public:
  OutputError(std::string path, std::string message);
  const std::string& path() const noexcept { return path_; }
  int exit_code() const noexcept override { return 3; }

 private:
  std::string path_;
};

// An output place that arnoldweb refuses to use whatever the options: it
// would replace something arnoldweb did not write (the current directory, a
// directory holding the scene or files of the user). Bad input: exit code 2.
class OutputRefused : public OutputError {
 public:
  using OutputError::OutputError;
  int exit_code() const noexcept override { return 2; }
};

// An output directory read back (render, compare, the Python reader) that
// cannot be used as it is: missing, a file that is not a plain file, a
// summary.json of the wrong form, a file whose size or digest differs from
// what summary.json records, data of another shape than it declares. Bad
// input: exit code 2; `path` names the file.
class SavedRunError : public OutputError {
 public:
  using OutputError::OutputError;
  int exit_code() const noexcept override { return 2; }
};

// A checkpoint that cannot be used: damaged, written by another version, or
// of another scene. Bad input: exit code 2; the checkpoint is left as it is.
class CheckpointError : public Error {
 public:
  CheckpointError(const std::string& path, const std::string& message)
      : Error((path.empty() ? std::string() : path + ": ") + message) {}
  int exit_code() const noexcept override { return 2; }
};

// Initial states that cannot be used (states.hpp): a state file that cannot
// be read or breaks the schema, or a state that is not finite, out of range
// or far from the model's energy. `source` is the file (or "initial" for
// arrays), `dataset` the HDF5 dataset or attribute ("" if none), `row` the
// state counted from 0 (-1 if none). Bad input: exit code 2.
class StateError : public Error {
 public:
  StateError(std::string source, std::string dataset, std::int64_t row, std::string message);
  const std::string& source() const noexcept { return source_; }
  const std::string& dataset() const noexcept { return dataset_; }
  std::int64_t row() const noexcept { return row_; }
  const std::string& message() const noexcept { return message_; }
  int exit_code() const noexcept override { return 2; }

 private:
  std::string source_, dataset_, message_;
  std::int64_t row_;
};

// The user interrupted a run (SIGINT); what was computed has been written.
class Interrupted : public Error {
 public:
  Interrupted() : Error("interrupted") {}
  int exit_code() const noexcept override { return 130; }
};

}  // namespace arnoldweb
