// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A LAS file written back with a normal per point, as extra bytes named as
// PDAL names them.

#ifndef CGAL_RRHT_IO_WRITE_LAS_WITH_NORMALS_H
#define CGAL_RRHT_IO_WRITE_LAS_WITH_NORMALS_H

#include <CGAL/RRHT/IO/LAS_file.h>
#include <CGAL/RRHT/IO/internal/LAS_layout.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace IO {

/// \ingroup PkgRRHTRef
/// The names of the extra bytes that hold the normal's coordinates, as
/// PDAL's `filters.normal` and `writers.las` name them, and the confidence.
inline const std::array<const char*, 4> LAS_normal_names = { "NormalX", "NormalY", "NormalZ", "NormalConfidence" };

namespace internal {

// Where each value of a point goes in the output's records: the offset of
// a field already there, or of one appended after the input's bytes.
struct Normal_fields
{
  std::vector<std::size_t> offsets;
  std::vector<std::string> appended; // names, in the order they are appended
  std::size_t input_length = 0, output_length = 0;
  std::vector<unsigned char> payload; // of the output's extra-bytes record
};

inline Normal_fields normal_fields(const LAS_file& input, std::size_t values, const std::vector<unsigned char>& payload)
{
  namespace e = extra_bytes;
  Normal_fields fields;
  fields.input_length = fields.output_length = input.record_length();
  fields.payload = payload;
  std::size_t appended = input.record_length();
  for(std::size_t i = 0; i < values; ++i)
  {
    const std::string name = LAS_normal_names[i];
    auto field = std::find_if(input.extra_bytes().begin(), input.extra_bytes().end(),
                              [&](const LAS_extra_bytes_field& f) { return f.name == name; });
    if(field == input.extra_bytes().end())
    {
      fields.offsets.push_back(appended);
      fields.appended.push_back(name);
      appended += 8;
    }
    else if(field->data_type == e::double_type)
      fields.offsets.push_back(field->offset); // written over, as a second run would
    else
      throw LAS_error(input.path() + ": its extra bytes '" + name + "' are of data type " +
                      std::to_string(field->data_type) + ", not double (10): they cannot hold the normal");
  }
  if(fields.appended.empty())
    return fields;
  if(appended > (std::numeric_limits<std::uint16_t>::max)())
    throw LAS_error(input.path() + ": point records of " + std::to_string(appended) +
                    " bytes with the normals, more than LAS allows (65535)");
  fields.output_length = appended;
  // Extra bytes that no descriptor covers are described as undocumented
  // bytes first, so that the normals are found where the descriptors say.
  std::size_t documented = standard_record_length(input.point_format());
  for(const LAS_extra_bytes_field& field : input.extra_bytes())
    documented = field.offset + field.size;
  auto add_descriptor = [&](unsigned int data_type, unsigned int options, const std::string& name,
                            const std::string& description) {
    const std::size_t at = fields.payload.size();
    fields.payload.resize(at + e::size, 0);
    fields.payload[at + e::data_type] = static_cast<unsigned char>(data_type);
    fields.payload[at + e::options] = static_cast<unsigned char>(options);
    write_text(&fields.payload[at + e::name], name, 32);
    write_text(&fields.payload[at + e::description], description, 32);
  };
  for(std::size_t left = input.record_length() - documented; left > 0;)
  {
    const std::size_t bytes = (std::min<std::size_t>)(left, 255);
    add_descriptor(e::undocumented, unsigned(bytes), "undocumented", "");
    left -= bytes;
  }
  for(const std::string& name : fields.appended)
    add_descriptor(e::double_type, 0, name, name == "NormalConfidence" ? "confidence of the normal, 0 to 1"
                                                                         : "coordinate of the unit normal");
  return fields;
}

// Copies `count` bytes of `in` from `at` to `out`.
inline void copy_bytes(const LAS_file& input, std::ifstream& in, std::uint64_t at, std::uint64_t count,
                       std::ostream& out)
{
  std::vector<char> buffer(1 << 16);
  in.clear();
  in.seekg(std::streamoff(at));
  while(count > 0)
  {
    const std::size_t n = std::size_t((std::min<std::uint64_t>)(count, buffer.size()));
    if(!in.read(buffer.data(), std::streamsize(n)))
      throw LAS_error(input.path() + ": could not read " + std::to_string(n) + " bytes at byte " + std::to_string(at));
    out.write(buffer.data(), std::streamsize(n));
    count -= n, at += n;
  }
}

// A variable-length record's header, regular or extended, with `length`
// bytes after it.
inline std::vector<unsigned char> record_header(const LAS_record& record, std::uint64_t length,
                                                const std::vector<unsigned char>& original)
{
  std::vector<unsigned char> header = original;
  if(record.extended)
    write_unsigned<std::uint64_t>(&header[vlr::length_after_header], length);
  else
    write_unsigned<std::uint16_t>(&header[vlr::length_after_header], std::uint16_t(length));
  return header;
}

} // namespace internal

/// \ingroup PkgRRHTRef
/// Writes to `out` the LAS file `input` with one normal per point record:
/// every record kept byte for byte and followed by the normal's
/// coordinates as extra bytes `NormalX`, `NormalY`, `NormalZ` (doubles,
/// data type 10), then `NormalConfidence` if `confidences` is not null.
/// The extra-bytes record (LASF_Spec / 4, LAS 1.4 R15 Section 4.3) gets a
/// descriptor for each, after those of the input, which it keeps; extra
/// bytes of the input that no descriptor covers get one of undocumented
/// bytes first, as the specification asks. Fields of these names already
/// in the input, of type double, are written over instead. The output is
/// LAS 1.4, whose extra-bytes record PDAL's `readers.las` reads without
/// options: an older header gets the fields of 1.4 (every point format of
/// 1.0 to 1.3 is one of 1.4's). The header's other fields, every other
/// variable-length record (the coordinate reference system among them) and
/// every byte after the points are kept; the offsets that the longer
/// records move are updated, and the bounds and the counts of points by
/// return are computed from the records.
///
/// \param input the LAS file whose records are written
/// \param out a binary stream, at its beginning (the header is written again at the end)
/// \param normals 3 numbers per point record, in the order of the records
/// \param confidences 1 number per point record, or null
/// \throws LAS_error if the input cannot be read or the output would not
/// be a valid LAS file.
inline void write_LAS_with_normals(const LAS_file& input, std::ostream& out, const double* normals,
                                   const double* confidences = nullptr)
{
  namespace h = internal::header;
  namespace v = internal::vlr;
  const std::size_t values = confidences ? 4 : 3;
  std::ifstream in(input.path(), std::ios::binary);
  if(!in)
    throw LAS_error(input.path() + ": cannot be opened");
  const LAS_record* extra = input.extra_bytes_record();
  std::vector<unsigned char> payload, extra_header;
  if(extra)
  {
    const std::size_t header_size = extra->extended ? v::extended_size : v::size;
    extra_header.resize(header_size);
    payload.resize(std::size_t(extra->length));
    std::vector<unsigned char> bytes(header_size + payload.size());
    in.seekg(std::streamoff(extra->begin));
    if(!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
      throw LAS_error(input.path() + ": could not read its extra-bytes record");
    std::copy(bytes.begin(), bytes.begin() + header_size, extra_header.begin());
    std::copy(bytes.begin() + header_size, bytes.end(), payload.begin());
  }
  const internal::Normal_fields fields = internal::normal_fields(input, values, payload);
  const bool new_descriptors = !fields.appended.empty();
  const std::uint64_t payload_growth = fields.payload.size() - payload.size();
  LAS_record added; // a new regular extra-bytes record, if needed
  if(new_descriptors && !extra)
  {
    added.user_id = "LASF_Spec";
    added.record_id = 4;
    extra_header.assign(v::size, 0);
    internal::write_text(&extra_header[v::user_id], "LASF_Spec", 16);
    internal::write_unsigned<std::uint16_t>(&extra_header[v::record_id], 4);
    internal::write_text(&extra_header[v::description], "Extra Bytes Record", 32);
  }
  const bool regular = new_descriptors && (!extra || !extra->extended);
  // The output is LAS 1.4: PDAL reads an extra-bytes record only in a 1.4
  // file unless told otherwise, and every format of 1.0 to 1.3 is one of
  // 1.4's. An older header gets 1.4's fields, after its own.
  const unsigned int minor = input.version_minor();
  const std::uint64_t header_growth = h::least_size(4) - h::least_size(minor);
  const std::uint64_t growth_before_points = header_growth + (regular ? payload_growth + (extra ? 0 : v::size) : 0);
  if(regular && fields.payload.size() > (std::numeric_limits<std::uint16_t>::max)())
    throw LAS_error(input.path() + ": its extra-bytes record would be longer than a variable-length record can be");
  if(input.points_begin() + growth_before_points > (std::numeric_limits<std::uint32_t>::max)())
    throw LAS_error(input.path() + ": its point records would begin past the 4 GiB that LAS can address");
  const std::uint64_t n = input.size();
  const std::uint64_t points_growth = n * (fields.output_length - fields.input_length);
  // Where a byte after the points of the input is in the output.
  auto moved = [&](std::uint64_t at) {
    std::uint64_t to = at + growth_before_points + points_growth;
    if(new_descriptors && extra && extra->extended && at > extra->begin)
      to += payload_growth;
    return to;
  };

  // The header, its bounds and counts written once the points are read.
  // User-defined bytes after an older header's fields stay after 1.4's.
  const std::vector<unsigned char>& original = input.header();
  std::vector<unsigned char> header(original.begin(), original.begin() + h::least_size(minor));
  header.resize(h::least_size(4), 0);
  header.insert(header.end(), original.begin() + h::least_size(minor), original.end());
  header[h::version_minor] = 4;
  internal::write_unsigned<std::uint16_t>(&header[h::header_size], std::uint16_t(header.size()));
  internal::write_unsigned<std::uint32_t>(&header[h::offset_to_point_data],
                                          std::uint32_t(input.points_begin() + growth_before_points));
  if(new_descriptors && !extra)
    internal::write_unsigned<std::uint32_t>(
      &header[h::number_of_vlrs], internal::read_unsigned<std::uint32_t>(&header[h::number_of_vlrs]) + 1);
  internal::write_unsigned<std::uint16_t>(&header[h::record_length], std::uint16_t(fields.output_length));
  if(minor >= 3)
  {
    const std::uint64_t waveform = internal::read_unsigned<std::uint64_t>(&header[h::start_of_waveform_data]);
    if(waveform >= input.points_end())
    {
      internal::write_unsigned<std::uint64_t>(&header[h::start_of_waveform_data], moved(waveform));
      // LAS 1.3 stores the waveform data in the one extended record there.
      if(minor == 3)
      {
        internal::write_unsigned<std::uint64_t>(&header[h::start_of_first_evlr], moved(waveform));
        internal::write_unsigned<std::uint32_t>(&header[h::number_of_evlrs], 1);
      }
    }
  }
  if(minor >= 4)
  {
    const std::uint64_t first = internal::read_unsigned<std::uint64_t>(&header[h::start_of_first_evlr]);
    if(internal::read_unsigned<std::uint32_t>(&header[h::number_of_evlrs]) > 0)
      internal::write_unsigned<std::uint64_t>(&header[h::start_of_first_evlr], moved(first));
  }
  out.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));

  // The regular records, and the bytes before the points.
  auto write_extra_bytes_record = [&](const LAS_record& record) {
    const std::vector<unsigned char> bytes = internal::record_header(record, fields.payload.size(), extra_header);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.write(reinterpret_cast<const char*>(fields.payload.data()), std::streamsize(fields.payload.size()));
  };
  std::uint64_t at = input.header().size();
  for(const LAS_record& record : input.records())
  {
    if(record.extended)
      break;
    if(&record == extra && new_descriptors)
    {
      internal::copy_bytes(input, in, at, record.begin - at, out);
      write_extra_bytes_record(record);
      at = record.end();
    }
  }
  std::uint64_t regular_end = input.header().size();
  for(const LAS_record& record : input.records())
    if(!record.extended)
      regular_end = record.end();
  internal::copy_bytes(input, in, at, regular_end - at, out);
  if(new_descriptors && !extra)
    write_extra_bytes_record(added);
  internal::copy_bytes(input, in, regular_end, input.points_begin() - regular_end, out);

  // The points, by chunks of records.
  std::array<double, 6> bounds = { -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL }; // max, min
  std::array<std::uint64_t, 15> by_return{};
  const std::uint64_t chunk = (std::max<std::uint64_t>)(1, (1u << 22) / fields.output_length);
  std::vector<unsigned char> records, written;
  for(std::uint64_t first = 0; first < n; first += chunk)
  {
    const std::size_t count = std::size_t((std::min)(chunk, n - first));
    records.resize(count * fields.input_length);
    written.assign(count * fields.output_length, 0);
    input.read_records(first, count, records.data());
    for(std::size_t i = 0; i < count; ++i)
    {
      const unsigned char* record = &records[i * fields.input_length];
      unsigned char* copy = &written[i * fields.output_length];
      std::copy(record, record + fields.input_length, copy);
      const std::uint64_t point = first + i;
      for(std::size_t value = 0; value < values; ++value)
        internal::write_double(copy + fields.offsets[value],
                               value < 3 ? normals[3 * point + value] : confidences[point]);
      double xyz[3];
      input.coordinates(record, xyz);
      for(int axis = 0; axis < 3; ++axis)
      {
        bounds[2 * axis] = (std::max)(bounds[2 * axis], xyz[axis]);
        bounds[2 * axis + 1] = (std::min)(bounds[2 * axis + 1], xyz[axis]);
      }
      const unsigned int r = internal::return_number(record, input.point_format());
      if(r >= 1)
        ++by_return[r - 1];
    }
    out.write(reinterpret_cast<const char*>(written.data()), std::streamsize(written.size()));
  }

  // The bytes after the points: the extended records among them.
  at = input.points_end();
  if(new_descriptors && extra && extra->extended)
  {
    internal::copy_bytes(input, in, at, extra->begin - at, out);
    write_extra_bytes_record(*extra);
    at = extra->end();
  }
  internal::copy_bytes(input, in, at, input.file_size() - at, out);

  // The bounds and the counts (Section 2.4): the legacy fields hold them for
  // formats 0 to 5 when they fit, LAS 1.4's for every format.
  if(n == 0)
    bounds.fill(0.);
  for(int i = 0; i < 6; ++i)
    internal::write_double(&header[h::bounds + 8 * i], bounds[i]);
  const bool legacy = input.point_format() < 6 && n <= (std::numeric_limits<std::uint32_t>::max)();
  internal::write_unsigned<std::uint32_t>(&header[h::legacy_number_of_points], legacy ? std::uint32_t(n) : 0u);
  for(int i = 0; i < 5; ++i)
    internal::write_unsigned<std::uint32_t>(&header[h::legacy_points_by_return + 4 * i],
                                            legacy ? std::uint32_t(by_return[i]) : 0u);
  internal::write_unsigned<std::uint64_t>(&header[h::number_of_points], n);
  for(int i = 0; i < 15; ++i)
    internal::write_unsigned<std::uint64_t>(&header[h::points_by_return + 8 * i], by_return[i]);
  out.seekp(0);
  out.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));
  if(!out)
    throw LAS_error("could not write the LAS file with the normals of " + input.path());
}

/// \ingroup PkgRRHTRef
/// Writes the file `output` as the function above writes a stream, through
/// a temporary file in the same folder renamed at the end: a failed write
/// leaves no partial file in place of an earlier one.
/// \param input the LAS file whose records are written
/// \param output the path of the file written
/// \param normals 3 numbers per point record, in the order of the records
/// \param confidences 1 number per point record, or null
/// \throws LAS_error if the input cannot be read or the output cannot be
/// written, `std::filesystem::filesystem_error` if the temporary file cannot
/// be renamed.
inline void write_LAS_with_normals(const LAS_file& input, const std::string& output, const double* normals,
                                   const double* confidences = nullptr)
{
  namespace fs = std::filesystem;
  const fs::path target(output);
  const std::size_t unique = std::hash<std::thread::id>()(std::this_thread::get_id()) ^
                             std::size_t(std::chrono::steady_clock::now().time_since_epoch().count());
  const fs::path temporary =
    target.parent_path() / ("." + target.filename().string() + ".partial." + std::to_string(unique) + ".las");
  try
  {
    {
      std::ofstream out(temporary, std::ios::binary);
      if(!out)
        throw LAS_error(output + ": cannot be written");
      write_LAS_with_normals(input, out, normals, confidences);
      out.close();
      if(!out)
        throw LAS_error(output + ": could not be written in full");
    }
    fs::rename(temporary, target);
  }
  catch(...)
  {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

} // namespace IO
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_IO_WRITE_LAS_WITH_NORMALS_H
