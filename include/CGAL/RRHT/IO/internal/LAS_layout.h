// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where things are in an uncompressed LAS file, versions 1.0 to 1.4
// (ASPRS LAS 1.4 R15), and its little-endian numbers read and written
// whatever the machine's byte order.

#ifndef CGAL_RRHT_IO_INTERNAL_LAS_LAYOUT_H
#define CGAL_RRHT_IO_INTERNAL_LAS_LAYOUT_H

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace CGAL {
namespace RRHT {
namespace IO {
namespace internal {

/// Byte offsets of the Public Header Block's fields (Section 2.4, Table 3).
namespace header {
constexpr std::size_t global_encoding = 6;
constexpr std::size_t version_major = 24;
constexpr std::size_t version_minor = 25;
constexpr std::size_t header_size = 94;
constexpr std::size_t offset_to_point_data = 96;
constexpr std::size_t number_of_vlrs = 100;
constexpr std::size_t point_format = 104;
constexpr std::size_t record_length = 105;
constexpr std::size_t legacy_number_of_points = 107;
constexpr std::size_t legacy_points_by_return = 111; // uint32_t[5]
constexpr std::size_t scale = 131;                   // double[3], x y z
constexpr std::size_t offset = 155;                  // double[3]
constexpr std::size_t bounds = 179;                  // max x, min x, max y, min y, max z, min z
constexpr std::size_t start_of_waveform_data = 227;  // LAS 1.3 and later
constexpr std::size_t start_of_first_evlr = 235;     // LAS 1.4
constexpr std::size_t number_of_evlrs = 243;
constexpr std::size_t number_of_points = 247;
constexpr std::size_t points_by_return = 255; // uint64_t[15]

/// The smallest header of each minor version: 1.0 to 1.2, 1.3, 1.4.
inline std::size_t least_size(unsigned int minor) { return minor >= 4 ? 375 : minor == 3 ? 235 : 227; }
} // namespace header

/// A variable-length record's header: 54 bytes before its payload, 60 for
/// an extended one (Sections 2.5 and 2.7).
namespace vlr {
constexpr std::size_t user_id = 2; // char[16]
constexpr std::size_t record_id = 18;
constexpr std::size_t length_after_header = 20; // uint16_t; uint64_t in an extended record
constexpr std::size_t description = 22;         // char[32]; at 28 in an extended record
constexpr std::size_t size = 54;
constexpr std::size_t extended_size = 60;
} // namespace vlr

/// One extra-bytes descriptor, of the payload of the record LASF_Spec / 4
/// (Section 4.3): 192 bytes.
namespace extra_bytes {
constexpr std::size_t data_type = 2;
constexpr std::size_t options = 3;
constexpr std::size_t name = 4; // char[32]
constexpr std::size_t scale = 112;       // double, of the first member
constexpr std::size_t offset = 136;      // double, of the first member
constexpr std::size_t description = 160; // char[32]
constexpr unsigned int scale_bit = 1u << 3; // of `options`: the scale is given
constexpr unsigned int offset_bit = 1u << 4; // the offset is given
constexpr std::size_t size = 192;
constexpr unsigned int undocumented = 0; // data_type 0: `options` bytes of unknown meaning
constexpr unsigned int double_type = 10;

/// The size of a value of `data_type` 1 to 30 (the two- and three-member
/// arrays 11 to 30, deprecated in R14, are still in files), 0 for a data
/// type the specification reserves.
inline std::size_t size_of(unsigned int data_type)
{
  static const unsigned char sizes[] = { 1, 1, 2, 2, 4, 4, 8, 8, 4, 8 };
  if(data_type >= 1 && data_type <= 10)
    return sizes[data_type - 1];
  if(data_type >= 11 && data_type <= 30)
    return std::size_t((data_type - 1) / 10 + 1) * sizes[(data_type - 1) % 10];
  return 0;
}
} // namespace extra_bytes

/// The length of a point record of format 0 to 10, without extra bytes
/// (Section 2.6, Tables 7 to 16).
inline std::size_t standard_record_length(unsigned int format)
{
  static const unsigned char lengths[] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };
  return lengths[format];
}

/// The return number of a point record: 3 bits in formats 0 to 5, 4 in
/// formats 6 to 10, the low bits of the byte at 14.
inline unsigned int return_number(const unsigned char* record, unsigned int format)
{
  return record[14] & (format >= 6 ? 0x0F : 0x07);
}

template <typename Unsigned>
Unsigned read_unsigned(const unsigned char* bytes)
{
  Unsigned value = 0;
  for(std::size_t i = sizeof(Unsigned); i-- > 0;)
    value = Unsigned((value << 8) | bytes[i]);
  return value;
}

inline std::int32_t read_int32(const unsigned char* bytes)
{
  const std::uint32_t u = read_unsigned<std::uint32_t>(bytes);
  std::int32_t value;
  std::memcpy(&value, &u, 4);
  return value;
}

inline double read_double(const unsigned char* bytes)
{
  const std::uint64_t u = read_unsigned<std::uint64_t>(bytes);
  double value;
  std::memcpy(&value, &u, 8);
  return value;
}

/// A value of the extra bytes' scalar data type 1 to 10 (Section 4.3,
/// Table 25), as a double: rounded to it for 64-bit integers beyond 2^53.
inline double read_value(const unsigned char* bytes, unsigned int data_type)
{
  auto as_signed = [](auto u, auto s) {
    std::memcpy(&s, &u, sizeof s);
    return double(s);
  };
  switch(data_type)
  {
  case 1: return bytes[0];
  case 2: return as_signed(bytes[0], std::int8_t());
  case 3: return read_unsigned<std::uint16_t>(bytes);
  case 4: return as_signed(read_unsigned<std::uint16_t>(bytes), std::int16_t());
  case 5: return read_unsigned<std::uint32_t>(bytes);
  case 6: return read_int32(bytes);
  case 7: return double(read_unsigned<std::uint64_t>(bytes));
  case 8: return as_signed(read_unsigned<std::uint64_t>(bytes), std::int64_t());
  case 9:
  {
    const std::uint32_t u = read_unsigned<std::uint32_t>(bytes);
    float value;
    std::memcpy(&value, &u, 4);
    return value;
  }
  default: return read_double(bytes);
  }
}

template <typename Unsigned>
void write_unsigned(unsigned char* bytes, Unsigned value)
{
  for(std::size_t i = 0; i < sizeof(Unsigned); ++i, value = Unsigned(value >> 8))
    bytes[i] = static_cast<unsigned char>(value & 0xFF);
}

inline void write_double(unsigned char* bytes, double value)
{
  std::uint64_t u;
  std::memcpy(&u, &value, 8);
  write_unsigned(bytes, u);
}

/// A fixed-length text field, without the zeros that pad it.
inline std::string read_text(const unsigned char* bytes, std::size_t size)
{
  std::size_t length = 0;
  while(length < size && bytes[length] != 0)
    ++length;
  return std::string(reinterpret_cast<const char*>(bytes), length);
}

/// Writes `text` in a field of `size` bytes, padded with zeros.
inline void write_text(unsigned char* bytes, const std::string& text, std::size_t size)
{
  std::memset(bytes, 0, size);
  std::memcpy(bytes, text.data(), text.size() < size ? text.size() : size);
}

} // namespace internal
} // namespace IO
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_IO_INTERNAL_LAS_LAYOUT_H
