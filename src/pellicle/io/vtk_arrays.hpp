#pragma once
//! Pieces of VTK XML files shared by the writers: inline binary data arrays (io/ only).

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/io/atomic_file.hpp"

namespace pellicle {

//! RFC 4648 base64 of a byte block.
inline void append_base64(std::string& out, const unsigned char* data, std::size_t n) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 2 < n; i += 3) {
    const unsigned v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i < n) {
    const unsigned v = (data[i] << 16) | (i + 1 < n ? data[i + 1] << 8 : 0);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += i + 1 < n ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
}

//! The opening tag of a <DataArray> in VTK's inline binary format.
inline std::string data_array_header(const char* type, const std::string& name, int components) {
  return "<DataArray type=\"" + std::string(type) + "\" Name=\"" + name +
         "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">\n";
}

//! One <DataArray> in VTK's inline binary format: base64 of a UInt64 byte count followed by
//! the little-endian values.
template <class T>
void data_array(std::string& out, const char* type, const std::string& name, int components,
                const std::vector<T>& values) {
  out += data_array_header(type, name, components);
  const std::uint64_t bytes = values.size() * sizeof(T);
  std::vector<unsigned char> block(sizeof(bytes) + bytes);
  std::memcpy(block.data(), &bytes, sizeof(bytes));
  if (bytes) std::memcpy(block.data() + sizeof(bytes), values.data(), bytes);
  append_base64(out, block.data(), block.size());
  out += "\n</DataArray>\n";
}

//! Base64 of a byte stream given in pieces, written to a file in pieces: the same text as
//! append_base64 of the whole stream.
class Base64Writer {
 public:
  explicit Base64Writer(AtomicFileWriter& file) : file_(file) {}
  void add(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    while (carried_ > 0 && carried_ < 3 && n > 0) carry_[carried_++] = *bytes++, --n;
    if (carried_ == 3) {
      append_base64(text_, carry_, 3);
      carried_ = 0;
    }
    const std::size_t whole = n / 3 * 3;
    append_base64(text_, bytes, whole);
    for (std::size_t i = whole; i < n; ++i) carry_[carried_++] = bytes[i];
    if (text_.size() >= kFlushBytes) flush();
  }
  //! Encode what is carried (with padding) and write everything out.
  void finish() {
    append_base64(text_, carry_, carried_);
    carried_ = 0;
    flush();
  }

 private:
  static constexpr std::size_t kFlushBytes = 1 << 16;
  void flush() {
    file_.write(text_);
    text_.clear();
  }
  AtomicFileWriter& file_;
  std::string text_;
  unsigned char carry_[3];
  int carried_ = 0;
};

//! data_array() written straight to a file: `fill(first, last, out)` puts the values of
//! points [first, last) in `out` (components per point), a few thousand points at a time, so
//! no array of every point is ever built.
template <class T, class Fill>
void stream_data_array(AtomicFileWriter& file, const char* type, const std::string& name,
                       int components, std::size_t points, Fill&& fill) {
  file.write(data_array_header(type, name, components));
  const std::uint64_t bytes = points * components * sizeof(T);
  Base64Writer text(file);
  text.add(&bytes, sizeof(bytes));
  constexpr std::size_t kChunkPoints = 4096;
  std::vector<T> values(kChunkPoints * components);
  for (std::size_t first = 0; first < points; first += kChunkPoints) {
    const std::size_t last = std::min(points, first + kChunkPoints);
    fill(first, last, values.data());
    text.add(values.data(), (last - first) * components * sizeof(T));
  }
  text.finish();
  file.write("\n</DataArray>\n");
}

template <int D>
std::vector<double> as_xyz(const std::vector<Vec<D>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < D; ++d) out[3 * i + d] = v[i][d];
  return out;
}

}  // namespace pellicle
