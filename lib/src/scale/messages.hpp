// arnoldweb: the messages between the coordinator of a job spread over
// several devices and its workers (coordinator.hpp, worker.hpp), as bytes
// (byte_stream.hpp), the same in one process (threads) and between MPI ranks.
//   coordinator -> worker: Begin part k | End | Range first,count | Done | Snapshot
//   worker -> coordinator: Request (the finished range and its outputs, the
//                          size it wants, whether it was asked to stop)
//                        | Histograms (after Snapshot) | Final histograms
//                        | Error (text)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/device.hpp"

namespace arnoldweb::detail {

enum class MessageType : std::uint64_t { Begin = 1, End, Range, Done, Snapshot, Request, Histograms, Final, Error };

struct Message {
  MessageType type = MessageType::End;
  std::uint64_t part = 0;
  std::uint64_t first = 0, count = 0;  // Range; Request: the finished range (count 0: none)
  std::uint64_t want = 0;              // Request
  bool stop = false;                   // Request: a stop signal reached the worker
  ChunkOutput out;                     // Request
  std::vector<std::uint64_t> histograms;  // Histograms, Final
  std::string text;                    // Error
};

std::string encode(const Message& m);
Message decode(const std::string& bytes);  // throws std::runtime_error

}  // namespace arnoldweb::detail
