#pragma once
//! Pieces of VTK XML files shared by the writers: inline binary data arrays (io/ only).

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"

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

//! One <DataArray> in VTK's inline binary format: base64 of a UInt64 byte count followed by
//! the little-endian values.
template <class T>
void data_array(std::string& out, const char* type, const std::string& name, int components,
                const std::vector<T>& values) {
  out += "<DataArray type=\"" + std::string(type) + "\" Name=\"" + name +
         "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">\n";
  const std::uint64_t bytes = values.size() * sizeof(T);
  std::vector<unsigned char> block(sizeof(bytes) + bytes);
  std::memcpy(block.data(), &bytes, sizeof(bytes));
  if (bytes) std::memcpy(block.data() + sizeof(bytes), values.data(), bytes);
  append_base64(out, block.data(), block.size());
  out += "\n</DataArray>\n";
}

template <int D>
std::vector<double> as_xyz(const std::vector<Vec<D>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < D; ++d) out[3 * i + d] = v[i][d];
  return out;
}

}  // namespace pellicle
