// arnoldweb: messages of a job over several devices (messages.hpp).
#include "scale/messages.hpp"

#include <stdexcept>

#include "run/byte_stream.hpp"

namespace arnoldweb::detail {

std::string encode(const Message& m) {
  ByteWriter w;
  w.u64(static_cast<std::uint64_t>(m.type));
  w.u64(m.part);
  w.u64(m.first);
  w.u64(m.count);
  w.u64(m.want);
  w.u64(m.stop ? 1 : 0);
  if (m.type == MessageType::Request) {
    w.array(m.out.counters);
    w.array(m.out.group_stats);
    w.array(m.out.rec_r);
    w.array(m.out.rec_i);
  }
  if (m.type == MessageType::Histograms || m.type == MessageType::Final) w.array(m.histograms);
  if (m.type == MessageType::Error) w.text(m.text);
  return std::move(w.bytes());
}

Message decode(const std::string& bytes) {
  ByteReader in(bytes);
  Message m;
  const std::uint64_t type = in.u64();
  if (type < 1 || type > static_cast<std::uint64_t>(MessageType::Error)) throw std::runtime_error("unknown message");
  m.type = static_cast<MessageType>(type);
  m.part = in.u64();
  m.first = in.u64();
  m.count = in.u64();
  m.want = in.u64();
  m.stop = in.u64() != 0;
  if (m.type == MessageType::Request) {
    m.out.counters = in.array<std::uint32_t>();
    m.out.group_stats = in.array<double>();
    m.out.rec_r = in.array<double>();
    m.out.rec_i = in.array<std::int64_t>();
  }
  if (m.type == MessageType::Histograms || m.type == MessageType::Final) m.histograms = in.array<std::uint64_t>();
  if (m.type == MessageType::Error) m.text = in.text();
  if (!in.at_end()) throw std::runtime_error("a message longer than its contents");
  return m;
}

}  // namespace arnoldweb::detail
