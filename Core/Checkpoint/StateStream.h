#pragma once
// Byte streams for checkpoints: a writer that appends plain values, vectors
// and strings, and a reader that takes them back in the same order and
// refuses to read past the end (a truncated or foreign file is an
// InputError, never a crash).
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "Base/Error.h"

namespace soak {

class StateWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  template <class T>
  void putVector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    put<std::uint64_t>(values.size());
    const auto* p = reinterpret_cast<const char*>(values.data());
    bytes_.insert(bytes_.end(), p, p + values.size() * sizeof(T));
  }
  void putString(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class StateReader {
 public:
  // `what` names the source in messages (e.g. the checkpoint's path).
  StateReader(const char* data, std::size_t size, std::string what)
      : data_(data), size_(size), what_(std::move(what)) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getVector() {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > (size_ - pos_) / sizeof(T)) fail("an array is longer than the data left");
    std::vector<T> values(n);
    if (n > 0) std::memcpy(values.data(), take(n * sizeof(T)), n * sizeof(T));
    return values;
  }
  std::string getString() {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > size_ - pos_) fail("a name is longer than the data left");
    const char* p = take(n);
    return std::string(p, p + n);
  }
  // Reads a string and refuses the stream unless it equals `expected` (section tags).
  void expect(const std::string& expected) {
    const std::string got = getString();
    if (got != expected) fail("expected section '" + expected + "', found '" + got + "'");
  }
  bool atEnd() const { return pos_ == size_; }
  std::size_t offset() const { return pos_; }  // bytes read so far
  std::size_t remaining() const { return size_ - pos_; }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("checkpoint is not readable: " + why, what_);
  }

 private:
  const char* take(std::size_t n) {
    if (n > size_ - pos_) fail("it ends early (truncated?)");
    const char* p = data_ + pos_;
    pos_ += n;
    return p;
  }
  const char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string what_;
};

}  // namespace soak
