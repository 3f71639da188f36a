// arnoldweb: little-endian byte images of plain values and arrays, for
// checkpoints and for messages between processes. A Reader that runs past
// the end, or finds a length that cannot be, throws std::runtime_error (the
// caller says which file or message was bad).
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace arnoldweb::detail {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "images are written little-endian as stored");

class ByteWriter {
 public:
  void u64(std::uint64_t v) { raw(&v, 8); }
  void f64(double v) { raw(&v, 8); }
  void text(const std::string& s) {
    u64(s.size());
    out_ += s;
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(sizeof(T) == 8 || sizeof(T) == 4, "plain 4- or 8-byte values");
    u64(v.size());
    raw(v.data(), v.size() * sizeof(T));
  }
  std::string& bytes() { return out_; }

 private:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  std::string out_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& in) : in_(in) {}
  std::uint64_t u64() {
    std::uint64_t v = 0;
    raw(&v, 8);
    return v;
  }
  double f64() {
    double v = 0;
    raw(&v, 8);
    return v;
  }
  std::string text() {
    const std::uint64_t n = u64();
    need(n);
    std::string s = in_.substr(at_, n);
    at_ += n;
    return s;
  }
  template <class T>
  std::vector<T> array() {
    const std::uint64_t n = u64();
    if (n > (in_.size() - at_) / sizeof(T)) throw std::runtime_error("an array longer than the data");
    std::vector<T> v(n);
    raw(v.data(), n * sizeof(T));
    return v;
  }
  bool at_end() const { return at_ == in_.size(); }

 private:
  void need(std::uint64_t n) const {
    if (n > in_.size() - at_) throw std::runtime_error("the data ends early");
  }
  void raw(void* p, std::size_t n) {
    need(n);
    if (n == 0) return;  // an empty vector's data() may be null: memcpy must not see it
    std::memcpy(p, in_.data() + at_, n);
    at_ += n;
  }
  const std::string& in_;
  std::size_t at_ = 0;
};

}  // namespace arnoldweb::detail
