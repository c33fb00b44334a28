#pragma once
// Reading back what the writers wrote: a whole file, and the values of a DataArray of a VTK
// XML file (raw binary, base64, with a UInt64 byte count in front).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pellicle::test {

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<unsigned char> base64_decode(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else
      continue;
    buffer = (buffer << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return out;
}

//! A DataArray of a VTK XML text: its NumberOfComponents and its values (the byte count in
//! the UInt64 header must match them).
template <class T>
std::vector<T> decoded_array(const std::string& xml, const std::string& name, int& components) {
  const auto at = xml.find("Name=\"" + name + "\"");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no array " << name;
    return {};
  }
  const auto tag_end = xml.find('>', at);
  const auto key = xml.find("NumberOfComponents=\"", at);
  components = std::stoi(xml.substr(key + std::strlen("NumberOfComponents=\"")));
  const auto end = xml.find("</DataArray>", tag_end);
  const auto bytes = base64_decode(xml.substr(tag_end + 1, end - tag_end - 1));
  std::uint64_t count;
  std::memcpy(&count, bytes.data(), 8);
  EXPECT_EQ(count + 8, bytes.size()) << name;
  std::vector<T> values(count / sizeof(T));
  std::memcpy(values.data(), bytes.data() + 8, count);
  return values;
}

}  // namespace pellicle::test
