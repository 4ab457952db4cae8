// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An uncompressed LAS file (ASPRS LAS 1.0 to 1.4, point formats 0 to 10),
// checked when opened, and its points read by ranges of records.

#ifndef CGAL_RRHT_IO_LAS_FILE_H
#define CGAL_RRHT_IO_LAS_FILE_H

#include <CGAL/RRHT/IO/internal/LAS_layout.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace IO {

/// \ingroup PkgRRHTRef
/// A LAS file that cannot be read or written as asked; the message names
/// the file and says what is wrong.
class LAS_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgRRHTRef
/// A variable-length record of a LAS file, regular (between the header and
/// the points) or extended (after the points; LAS 1.4 R15, Sections 2.5 and 2.7).
struct LAS_record
{
  std::string user_id;          ///< the user id, as `LASF_Projection` or `LASF_Spec`
  std::uint16_t record_id = 0;  ///< the record id, as 4 for the extra bytes of `LASF_Spec`
  bool extended = false;        ///< whether it is an extended record, after the points
  std::uint64_t begin = 0;      ///< where its header is in the file
  std::uint64_t length = 0;     ///< its payload's length, after its header
  /// \return where it ends in the file: its header's 54 bytes (60 for an
  /// extended record) and its payload after `begin`
  std::uint64_t end() const { return begin + (extended ? 60 : 54) + length; }
};

/// \ingroup PkgRRHTRef
/// One field of the extra bytes at the end of each point record, as the
/// extra-bytes record (LASF_Spec / 4) describes it (Section 4.3).
struct LAS_extra_bytes_field
{
  std::string name;           ///< its name, as `NormalX`
  unsigned int data_type = 0; ///< 1 to 10 (unsigned char to double), 11 to 30 arrays, 0 undocumented bytes
  std::size_t offset = 0;     ///< in the point record
  std::size_t size = 0;       ///< in bytes
  double scale = 1.;          ///< a value is the number stored times `scale` plus `value_offset`:
  double value_offset = 0.;   ///< 1 and 0 where the descriptor gives none
  /// \return whether the field holds one number (data type 1 to 10), which `LAS_file::read_field()` reads
  bool holds_one_number() const { return data_type >= 1 && data_type <= 10; }
};

/// \ingroup PkgRRHTRef
/// An uncompressed LAS file. Opening it reads its header and its
/// variable-length records and checks that they describe a file that can
/// be read: every check names what is wrong. A compressed (LAZ) file is
/// refused with the commands that decompress it. The points are then read
/// by ranges of records, each read opening the file anew: a `LAS_file` may
/// be read from several threads at once.
class LAS_file
{
public:
  /// Opens and checks the file at `path`.
  /// \param path the file's path
  /// \throws LAS_error if it cannot be read, is not an uncompressed LAS
  /// 1.0 to 1.4 file of point format 0 to 10, or is truncated or
  /// inconsistent.
  explicit LAS_file(const std::string& path)
    : m_path(path)
  {
    std::ifstream in(path, std::ios::binary);
    if(!in)
      fail("cannot be opened");
    in.seekg(0, std::ios::end);
    m_file_size = std::uint64_t(in.tellg());
    read_header(in);
    read_records(in);
    read_extra_bytes(in);
  }

  /// \return the path it was opened with
  const std::string& path() const { return m_path; }
  /// \return the size of the file, in bytes
  std::uint64_t file_size() const { return m_file_size; }
  /// \return the minor version of LAS 1.x, 0 to 4
  unsigned int version_minor() const { return m_header[internal::header::version_minor]; }
  /// \return the point data record format, 0 to 10
  unsigned int point_format() const { return m_format; }
  /// \return the length of a point record, extra bytes included
  std::size_t record_length() const { return m_record_length; }
  /// \return the number of point records
  std::uint64_t size() const { return m_size; }
  /// \return where the point records begin in the file
  std::uint64_t points_begin() const { return m_points_begin; }
  /// \return where the point records end in the file
  std::uint64_t points_end() const { return m_points_begin + m_size * m_record_length; }
  /// \return the Public Header Block as stored, user-defined bytes included
  const std::vector<unsigned char>& header() const { return m_header; }
  /// \return the scale of the coordinates: x = X * scale[0] + offset[0]
  const std::array<double, 3>& scale() const { return m_scale; }
  /// \return the offset of the coordinates
  const std::array<double, 3>& offset() const { return m_offset; }
  /// \return the variable-length records, regular then extended, in the file's order
  const std::vector<LAS_record>& records() const { return m_records; }
  /// \return the extra-bytes record, or null
  const LAS_record* extra_bytes_record() const
  {
    return m_extra_bytes_record == no_record ? nullptr : &m_records[m_extra_bytes_record];
  }
  /// \return the fields of the extra bytes that the extra-bytes record
  /// describes, in the records' order
  const std::vector<LAS_extra_bytes_field>& extra_bytes() const { return m_extra_bytes; }

  /// Reads the bytes of `count` point records from the record `first`.
  /// \param first the first record
  /// \param count the number of records
  /// \param out `count * record_length()` bytes
  /// \throws std::out_of_range if the records are not all in the file
  /// \throws LAS_error if the file cannot be read
  void read_records(std::uint64_t first, std::uint64_t count, unsigned char* out) const
  {
    if(first > m_size || count > m_size - first)
      throw std::out_of_range(m_path + ": records " + std::to_string(first) + " to " + std::to_string(first + count) +
                              " asked of " + std::to_string(m_size));
    if(count == 0)
      return;
    std::ifstream in(m_path, std::ios::binary);
    in.seekg(std::streamoff(m_points_begin + first * m_record_length));
    in.read(reinterpret_cast<char*>(out), std::streamsize(count * m_record_length));
    if(!in)
      fail("could not read its point records " + std::to_string(first) + " to " + std::to_string(first + count));
  }

  /// Writes to `xyz` the coordinates of `count` points from the record
  /// `first`, as x y z triples: X * scale + offset in double precision,
  /// as the specification defines them (Section 2.4).
  /// \param first the first record
  /// \param count the number of records
  /// \param xyz `3 * count` numbers
  void read_points(std::uint64_t first, std::uint64_t count, double* xyz) const
  {
    for_each_record(first, count,
                    [&](const unsigned char* record, std::uint64_t i) { coordinates(record, xyz + 3 * i); });
  }

  /// Writes to `values` the field `name` of the extra bytes of `count`
  /// points from the record `first`: the number stored times the scale
  /// plus the offset that its descriptor gives (Section 4.3).
  /// \param name the field's name
  /// \param first the first record
  /// \param count the number of records
  /// \param values `count` numbers
  /// \throws LAS_error if no field of one number has this name.
  void read_field(const std::string& name, std::uint64_t first, std::uint64_t count, double* values) const
  {
    const LAS_extra_bytes_field& field = extra_bytes_field(name);
    for_each_record(first, count, [&](const unsigned char* record, std::uint64_t i) {
      volatile double scaled = internal::read_value(record + field.offset, field.data_type) * field.scale;
      values[i] = scaled + field.value_offset; // as the coordinates: never one fused multiply-add
    });
  }

  /// \param name a field's name
  /// \return the field of one number (data type 1 to 10) named `name` of the extra bytes
  /// \throws LAS_error if there is none.
  const LAS_extra_bytes_field& extra_bytes_field(const std::string& name) const
  {
    std::string scalars;
    for(const LAS_extra_bytes_field& field : m_extra_bytes)
      if(field.holds_one_number())
      {
        if(field.name == name)
          return field;
        scalars += (scalars.empty() ? "'" : ", '") + field.name + "'";
      }
    fail("its extra bytes have no field of one number named '" + name + "' (" +
         (scalars.empty() ? std::string("they have none") : "they have " + scalars) + ")");
  }

  /// Writes to `xyz` the coordinates of one point record, as `read_points()` gives them.
  /// \param record the bytes of a point record
  /// \param xyz 3 numbers
  void coordinates(const unsigned char* record, double* xyz) const
  {
    for(int axis = 0; axis < 3; ++axis)
    {
      // Two roundings, never one fused multiply-add: the same coordinates
      // on every machine and with every compiler's flags.
      volatile double scaled = double(internal::read_int32(record + 4 * axis)) * m_scale[axis];
      xyz[axis] = scaled + m_offset[axis];
    }
  }

private:
  static constexpr std::size_t no_record = std::size_t(-1);

  // Calls f(record, i) for the i-th of `count` point records from `first`,
  // read by chunks of about 4 MiB.
  template <typename F>
  void for_each_record(std::uint64_t first, std::uint64_t count, const F& f) const
  {
    const std::uint64_t chunk = (std::max<std::uint64_t>)(1, (1u << 22) / m_record_length);
    std::vector<unsigned char> records;
    for(std::uint64_t done = 0; done < count; done += chunk)
    {
      const std::uint64_t n = (std::min)(chunk, count - done);
      records.resize(std::size_t(n * m_record_length));
      read_records(first + done, n, records.data());
      for(std::size_t i = 0; i < n; ++i)
        f(records.data() + i * m_record_length, done + i);
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw LAS_error(m_path + ": " + what); }

  // The Public Header Block (Section 2.4).
  void read_header(std::ifstream& in)
  {
    namespace h = internal::header;
    unsigned char fixed[375] = {};
    in.seekg(0);
    in.read(reinterpret_cast<char*>(fixed), std::streamsize((std::min<std::uint64_t>)(375, m_file_size)));
    if(m_file_size < 4 || std::string(reinterpret_cast<char*>(fixed), 4) != "LASF")
      fail("not a LAS file: it does not begin with LASF");
    if(m_file_size < h::least_size(0))
      fail("truncated: " + std::to_string(m_file_size) + " bytes, fewer than a LAS header");
    const unsigned int major = fixed[h::version_major], minor = fixed[h::version_minor];
    if(major != 1 || minor > 4)
      fail("LAS " + std::to_string(major) + "." + std::to_string(minor) + ": only LAS 1.0 to 1.4 is read");
    const std::size_t header_size = internal::read_unsigned<std::uint16_t>(fixed + h::header_size);
    if(header_size < h::least_size(minor))
      fail("its header size, " + std::to_string(header_size) + " bytes, is less than LAS 1." + std::to_string(minor) +
           "'s " + std::to_string(h::least_size(minor)));
    if(header_size > m_file_size)
      fail("truncated: its header of " + std::to_string(header_size) + " bytes is longer than the file");
    m_header.resize(header_size);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(m_header.data()), std::streamsize(header_size));
    const unsigned char* header = m_header.data();
    // LASzip marks a compressed file by setting the two high bits of the
    // point format.
    const unsigned int format_byte = header[h::point_format];
    if(format_byte & 0xC0)
      refuse_laz();
    m_format = format_byte;
    if(m_format > 10)
      fail("point format " + std::to_string(m_format) + ": LAS 1.4 defines formats 0 to 10");
    m_record_length = internal::read_unsigned<std::uint16_t>(header + h::record_length);
    const std::size_t standard = internal::standard_record_length(m_format);
    if(m_record_length < standard)
      fail("its point records of " + std::to_string(m_record_length) + " bytes are shorter than format " +
           std::to_string(m_format) + "'s " + std::to_string(standard));
    const std::uint64_t legacy = internal::read_unsigned<std::uint32_t>(header + h::legacy_number_of_points);
    m_size = legacy;
    if(minor >= 4)
    {
      m_size = internal::read_unsigned<std::uint64_t>(header + h::number_of_points);
      if(legacy != 0 && legacy != m_size)
        fail("its two point counts disagree: " + std::to_string(legacy) + " and " + std::to_string(m_size));
    }
    for(int axis = 0; axis < 3; ++axis)
    {
      m_scale[axis] = internal::read_double(header + h::scale + 8 * axis);
      m_offset[axis] = internal::read_double(header + h::offset + 8 * axis);
      if(!(std::abs(m_scale[axis]) > 0) || !std::isfinite(m_scale[axis]) || !std::isfinite(m_offset[axis]))
        fail(std::string("its ") + "xyz"[axis] + " scale and offset are not finite numbers with a nonzero scale");
    }
    m_points_begin = internal::read_unsigned<std::uint32_t>(header + h::offset_to_point_data);
    if(m_points_begin < header_size)
      fail("its point records begin inside its header");
    if(m_points_begin > m_file_size || m_size > (m_file_size - m_points_begin) / m_record_length)
      fail("truncated: " + std::to_string(m_size) + " point records of " + std::to_string(m_record_length) +
           " bytes announced from byte " + std::to_string(m_points_begin) + ", in a file of " +
           std::to_string(m_file_size) + " bytes");
  }

  // The regular variable-length records (Section 2.5), then the extended
  // ones (Section 2.7).
  void read_records(std::ifstream& in)
  {
    namespace h = internal::header;
    namespace v = internal::vlr;
    const std::uint32_t count = internal::read_unsigned<std::uint32_t>(m_header.data() + h::number_of_vlrs);
    std::uint64_t at = m_header.size();
    for(std::uint32_t i = 0; i < count; ++i)
    {
      unsigned char bytes[v::size];
      if(at + v::size > m_points_begin)
        fail("its variable-length record " + std::to_string(i + 1) + " of " + std::to_string(count) +
             " runs into its point records");
      read_at(in, at, bytes, v::size);
      LAS_record record{ internal::read_text(bytes + v::user_id, 16),
                         internal::read_unsigned<std::uint16_t>(bytes + v::record_id), false, at,
                         internal::read_unsigned<std::uint16_t>(bytes + v::length_after_header) };
      if(record.end() > m_points_begin)
        fail("its variable-length record " + std::to_string(i + 1) + " of " + std::to_string(count) + " (" +
             record.user_id + " / " + std::to_string(record.record_id) + ") runs into its point records");
      if(record.user_id == "laszip encoded")
        refuse_laz();
      at = record.end();
      m_records.push_back(record);
    }
    if(version_minor() < 4)
      return;
    const std::uint64_t first = internal::read_unsigned<std::uint64_t>(m_header.data() + h::start_of_first_evlr);
    const std::uint32_t extended = internal::read_unsigned<std::uint32_t>(m_header.data() + h::number_of_evlrs);
    if(extended == 0)
      return;
    if(first < points_end())
      fail("its extended variable-length records begin before the end of its point records");
    at = first;
    for(std::uint32_t i = 0; i < extended; ++i)
    {
      unsigned char bytes[v::extended_size];
      if(at > m_file_size || m_file_size - at < v::extended_size)
        fail("truncated: its extended variable-length record " + std::to_string(i + 1) + " of " +
             std::to_string(extended) + " is past the end");
      read_at(in, at, bytes, v::extended_size);
      LAS_record record{ internal::read_text(bytes + v::user_id, 16),
                         internal::read_unsigned<std::uint16_t>(bytes + v::record_id), true, at,
                         internal::read_unsigned<std::uint64_t>(bytes + v::length_after_header) };
      if(record.length > m_file_size - at - v::extended_size)
        fail("truncated: its extended variable-length record " + std::to_string(i + 1) + " of " +
             std::to_string(extended) + " (" + record.user_id + " / " + std::to_string(record.record_id) +
             ") is past the end");
      at = record.end();
      m_records.push_back(record);
    }
  }

  // The extra-bytes record (Section 4.3): one 192-byte descriptor per
  // field, fields in the order of the bytes after the format's own.
  void read_extra_bytes(std::ifstream& in)
  {
    namespace e = internal::extra_bytes;
    for(std::size_t i = 0; i < m_records.size(); ++i)
      if(m_records[i].user_id == "LASF_Spec" && m_records[i].record_id == 4)
      {
        if(m_extra_bytes_record != no_record)
          fail("it has two extra-bytes records");
        m_extra_bytes_record = i;
      }
    if(m_extra_bytes_record == no_record)
      return;
    const LAS_record& record = m_records[m_extra_bytes_record];
    if(record.length % e::size != 0)
      fail("its extra-bytes record of " + std::to_string(record.length) + " bytes is not a whole number of " +
           std::to_string(e::size) + "-byte descriptors");
    std::vector<unsigned char> payload(std::size_t(record.length));
    read_at(in, record.end() - record.length, payload.data(), payload.size());
    std::size_t at = internal::standard_record_length(m_format);
    for(std::size_t i = 0; i < payload.size(); i += e::size)
    {
      const unsigned char* descriptor = payload.data() + i;
      LAS_extra_bytes_field field;
      field.name = internal::read_text(descriptor + e::name, 32);
      field.data_type = descriptor[e::data_type];
      field.size = field.data_type == e::undocumented ? descriptor[e::options] : e::size_of(field.data_type);
      field.offset = at;
      const unsigned int options = field.data_type == e::undocumented ? 0 : descriptor[e::options];
      if(options & e::scale_bit)
        field.scale = internal::read_double(descriptor + e::scale);
      if(options & e::offset_bit)
        field.value_offset = internal::read_double(descriptor + e::offset);
      if(field.data_type != e::undocumented && field.size == 0)
        fail("its extra bytes '" + field.name + "' have the reserved data type " + std::to_string(field.data_type));
      at += field.size;
      if(at > m_record_length)
        fail("its extra-bytes record describes " + std::to_string(at - internal::standard_record_length(m_format)) +
             " or more extra bytes, more than the " +
             std::to_string(m_record_length - internal::standard_record_length(m_format)) + " of its point records");
      m_extra_bytes.push_back(field);
    }
  }

  void read_at(std::ifstream& in, std::uint64_t at, unsigned char* out, std::size_t size) const
  {
    in.clear();
    in.seekg(std::streamoff(at));
    in.read(reinterpret_cast<char*>(out), std::streamsize(size));
    if(!in)
      fail("could not read " + std::to_string(size) + " bytes at byte " + std::to_string(at));
  }

  [[noreturn]] void refuse_laz() const
  {
    fail("a LAZ (compressed LAS) file, which is not read: decompress it first, with 'pdal translate " + m_path +
         " points.las' or 'laszip -i " + m_path + " -o points.las'");
  }

  std::string m_path;
  std::uint64_t m_file_size = 0;
  std::vector<unsigned char> m_header;
  unsigned int m_format = 0;
  std::size_t m_record_length = 0;
  std::uint64_t m_size = 0;
  std::uint64_t m_points_begin = 0;
  std::array<double, 3> m_scale{}, m_offset{};
  std::vector<LAS_record> m_records;
  std::size_t m_extra_bytes_record = no_record;
  std::vector<LAS_extra_bytes_field> m_extra_bytes;
};

} // namespace IO
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_IO_LAS_FILE_H
