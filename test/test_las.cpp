// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// LAS files: read as other software wrote them, written back with the
// normals, and refused with a clear message when they cannot be read.

#include <CGAL/RRHT/IO/LAS_file.h>
#include <CGAL/RRHT/IO/write_LAS_with_normals.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using CGAL::RRHT::IO::LAS_error;
using CGAL::RRHT::IO::LAS_file;
namespace layout = CGAL::RRHT::IO::internal;

namespace {

const std::string data = std::string(RRHT_TEST_DATA) + "/las/";

std::vector<unsigned char> bytes_of(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A folder of its own for the files a test writes, removed with it.
struct Scratch_folder
{
  fs::path path;
  explicit Scratch_folder(const std::string& name)
    : path(fs::temp_directory_path() / ("rrht_las_" + name + "_" + std::to_string(std::random_device()())))
  {
    fs::create_directories(path);
  }
  ~Scratch_folder() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::vector<unsigned char>& bytes) const
  {
    std::ofstream(path / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    return path / name;
  }
};

// Sets the little-endian number at `at` of a file's bytes.
template <typename Number>
void set(std::vector<unsigned char>& bytes, std::size_t at, Number value)
{
  unsigned char encoded[sizeof(Number)];
  if constexpr(std::is_floating_point<Number>::value)
    layout::write_double(encoded, value);
  else
    layout::write_unsigned(encoded, value);
  for(std::size_t i = 0; i < sizeof(Number); ++i)
    bytes.at(at + i) = encoded[i];
}

std::vector<double> points_of(const LAS_file& file)
{
  std::vector<double> xyz(3 * file.size());
  file.read_points(0, file.size(), xyz.data());
  return xyz;
}

// Unit normals, different at every point, and confidences in [0, 1].
std::pair<std::vector<double>, std::vector<double>> some_normals(std::size_t n, unsigned int seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::vector<double> normals(3 * n), confidences(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    double x = normal(random), y = normal(random), z = normal(random);
    const double length = std::sqrt(x * x + y * y + z * z);
    normals[3 * i] = x / length, normals[3 * i + 1] = y / length, normals[3 * i + 2] = z / length;
    confidences[i] = std::uniform_real_distribution<double>()(random);
  }
  return { normals, confidences };
}

// The value of the double field `name` of every record of `file`.
std::vector<double> field_of(const LAS_file& file, const std::string& name)
{
  auto field = std::find_if(file.extra_bytes().begin(), file.extra_bytes().end(),
                            [&](const CGAL::RRHT::IO::LAS_extra_bytes_field& f) { return f.name == name; });
  REQUIRE(field != file.extra_bytes().end());
  REQUIRE(field->data_type == 10);
  std::vector<unsigned char> records(file.size() * file.record_length());
  file.read_records(0, file.size(), records.data());
  std::vector<double> values;
  for(std::size_t i = 0; i < file.size(); ++i)
    values.push_back(layout::read_double(&records[i * file.record_length() + field->offset]));
  return values;
}

void check_message(const std::string& path, const std::vector<std::string>& words)
{
  try
  {
    LAS_file file(path);
    FAIL("read without an error: " << path);
  }
  catch(const LAS_error& error)
  {
    const std::string message = error.what();
    INFO(message);
    CHECK(message.find(path) != std::string::npos);
    for(const std::string& word : words)
      CHECK(message.find(word) != std::string::npos);
  }
}

} // namespace

TEST_CASE("LAS files that other software wrote are read", "[las]")
{
  const LAS_file simple(data + "simple.las");
  CHECK(simple.version_minor() == 2);
  CHECK(simple.point_format() == 3);
  CHECK(simple.record_length() == 34);
  CHECK(simple.size() == 1065);
  CHECK(simple.records().empty());
  CHECK(simple.extra_bytes().empty());
  const std::vector<double> xyz = points_of(simple);
  // The first record holds X, Y, Z = 63701224, 84902831, 43166 with a scale
  // of 0.01 and an offset of -0.
  CHECK(xyz[0] == 63701224 * 0.01);
  CHECK(xyz[1] == 84902831 * 0.01);
  CHECK(xyz[2] == 43166 * 0.01);
  // Ranges read apart give the same points as one read.
  std::vector<double> part(3 * 100);
  simple.read_points(500, 100, part.data());
  CHECK(std::equal(part.begin(), part.end(), xyz.begin() + 3 * 500));

  // The same points in LAS 1.4 with five fields of extra bytes, among
  // them the deprecated arrays and undocumented bytes.
  const LAS_file extra(data + "extrabytes.las");
  CHECK(extra.version_minor() == 4);
  CHECK(extra.record_length() == 61);
  REQUIRE(extra.extra_bytes().size() == 5);
  const std::vector<std::pair<std::string, std::size_t>> fields = {
    { "Colors", 6 }, { "Reserved", 7 }, { "Flags", 2 }, { "Intensity", 4 }, { "Time", 8 }
  };
  std::size_t offset = 34;
  for(std::size_t i = 0; i < fields.size(); ++i)
  {
    CHECK(extra.extra_bytes()[i].name == fields[i].first);
    CHECK(extra.extra_bytes()[i].size == fields[i].second);
    CHECK(extra.extra_bytes()[i].offset == offset);
    offset += fields[i].second;
  }
  CHECK(points_of(extra) == xyz);
  // Its fields of one number: Intensity (4-byte unsigned integers) and Time
  // (8-byte ones), read as the bytes of the records say.
  std::vector<unsigned char> records(extra.size() * extra.record_length());
  extra.read_records(0, extra.size(), records.data());
  std::vector<double> values(extra.size() - 10);
  extra.read_field("Time", 10, values.size(), values.data());
  for(std::size_t i = 0; i < values.size(); ++i)
    CHECK(values[i] == double(layout::read_unsigned<std::uint64_t>(&records[(10 + i) * 61 + 53])));
  extra.read_field("Intensity", 10, values.size(), values.data());
  for(std::size_t i = 0; i < values.size(); ++i)
    CHECK(values[i] == double(layout::read_unsigned<std::uint32_t>(&records[(10 + i) * 61 + 49])));
  // The arrays and the undocumented bytes are not such fields.
  for(const std::string name : { "Colors", "Reserved", "Nope" })
    CHECK_THROWS_WITH(extra.read_field(name, 0, 1, values.data()),
                      Catch::Matchers::Contains("no field of one number named '" + name + "'") &&
                        Catch::Matchers::Contains("they have 'Intensity', 'Time'"));

  const LAS_file format6(data + "test1_4.las");
  CHECK(format6.point_format() == 6);
  CHECK(format6.size() == 1000);
  CHECK(format6.records().size() == 2);
  for(double c : points_of(format6))
    CHECK(std::isfinite(c));
}

TEST_CASE("A LAZ file is refused with the commands that decompress it", "[las]")
{
  check_message(data + "simple.laz", { "LAZ", "pdal translate", "laszip" });
}

TEST_CASE("LAS files written back with the normals keep every byte of their records", "[las]")
{
  const Scratch_folder folder("normals");
  for(const std::string name : { "simple.las", "extrabytes.las", "test1_4.las" })
    for(bool with_confidences : { false, true })
    {
      INFO(name << (with_confidences ? " with the confidences" : ""));
      const LAS_file input(data + name);
      const auto [normals, confidences] = some_normals(input.size(), 7);
      const fs::path path = folder.path / ("out_" + name);
      CGAL::RRHT::IO::write_LAS_with_normals(input, path.string(), normals.data(),
                                             with_confidences ? confidences.data() : nullptr);
      const LAS_file output(path.string());
      const std::size_t added = with_confidences ? 32 : 24;
      CHECK(output.version_minor() == 4);
      CHECK(output.point_format() == input.point_format());
      CHECK(output.size() == input.size());
      CHECK(output.record_length() == input.record_length() + added);
      CHECK(output.scale() == input.scale());
      CHECK(output.offset() == input.offset());

      // Every record's bytes, then the normals, bit for bit.
      std::vector<unsigned char> in(input.size() * input.record_length()), out(output.size() * output.record_length());
      input.read_records(0, input.size(), in.data());
      output.read_records(0, output.size(), out.data());
      bool kept = true;
      for(std::size_t i = 0; i < input.size(); ++i)
        kept = kept && std::equal(&in[i * input.record_length()], &in[(i + 1) * input.record_length()],
                                  &out[i * output.record_length()]);
      CHECK(kept);
      for(int axis = 0; axis < 3; ++axis)
      {
        const std::vector<double> values = field_of(output, CGAL::RRHT::IO::LAS_normal_names[axis]);
        bool same = true;
        for(std::size_t i = 0; i < values.size(); ++i)
          same = same && values[i] == normals[3 * i + axis];
        CHECK(same);
      }
      if(with_confidences)
        CHECK(field_of(output, "NormalConfidence") == confidences);

      // The input's descriptors, then the normals'.
      REQUIRE(output.extra_bytes().size() == input.extra_bytes().size() + added / 8);
      for(std::size_t i = 0; i < input.extra_bytes().size(); ++i)
        CHECK(output.extra_bytes()[i].name == input.extra_bytes()[i].name);
      CHECK(output.extra_bytes()[input.extra_bytes().size()].offset == input.record_length());

      // The same records (a new extra-bytes record last if there was none),
      // with the same payloads.
      REQUIRE(output.records().size() == input.records().size() + (input.extra_bytes_record() ? 0 : 1));
      const std::vector<unsigned char> input_bytes = bytes_of(data + name), output_bytes = bytes_of(path);
      for(std::size_t i = 0; i < input.records().size(); ++i)
      {
        const CGAL::RRHT::IO::LAS_record &a = input.records()[i], &b = output.records()[i];
        CHECK(a.user_id == b.user_id);
        CHECK(a.record_id == b.record_id);
        if(&a != input.extra_bytes_record())
          CHECK(std::equal(input_bytes.begin() + a.begin, input_bytes.begin() + a.end(),
                           output_bytes.begin() + b.begin, output_bytes.begin() + b.end()));
      }
      // The header's other fields as they were; the counts as they were,
      // but for the legacy ones of formats 6 to 10, zero as LAS 1.4 asks;
      // the bounds those of the points.
      CHECK(std::equal(input_bytes.begin(), input_bytes.begin() + 25, output_bytes.begin()));
      CHECK(std::equal(input_bytes.begin() + 26, input_bytes.begin() + 94, output_bytes.begin() + 26));
      CHECK(output.header().size() == 375);
      CHECK(std::equal(input_bytes.begin() + 131, input_bytes.begin() + 179, output_bytes.begin() + 131));
      if(input.point_format() < 6)
        CHECK(std::equal(input_bytes.begin() + 107, input_bytes.begin() + 131, output_bytes.begin() + 107));
      else
        CHECK(std::all_of(output_bytes.begin() + 107, output_bytes.begin() + 131, [](unsigned char b) { return b == 0; }));
      if(input.version_minor() >= 4)
        CHECK(std::equal(input_bytes.begin() + 247, input_bytes.begin() + 375, output_bytes.begin() + 247));
      else
        for(int i = 0; i < 5; ++i)
          CHECK(layout::read_unsigned<std::uint64_t>(&output_bytes[255 + 8 * i]) ==
                layout::read_unsigned<std::uint32_t>(&input_bytes[111 + 4 * i]));
      CHECK(layout::read_unsigned<std::uint64_t>(&output_bytes[247]) == input.size());
      const std::vector<double> xyz = points_of(output);
      for(int axis = 0; axis < 3; ++axis)
      {
        double high = -HUGE_VAL, low = HUGE_VAL;
        for(std::size_t i = 0; i < output.size(); ++i)
          high = (std::max)(high, xyz[3 * i + axis]), low = (std::min)(low, xyz[3 * i + axis]);
        CHECK(layout::read_double(&output.header()[179 + 16 * axis]) == high);
        CHECK(layout::read_double(&output.header()[187 + 16 * axis]) == low);
        // The input's bounds, from coordinates before they were rounded to
        // the scale, within a step of it.
        CHECK(std::abs(layout::read_double(&input.header()[179 + 16 * axis]) - high) <= input.scale()[axis]);
        CHECK(std::abs(layout::read_double(&input.header()[187 + 16 * axis]) - low) <= input.scale()[axis]);
      }
      CHECK(points_of(input) == xyz);
    }
}

TEST_CASE("A LAS file with normals written again gets its normals written over", "[las]")
{
  const Scratch_folder folder("again");
  const LAS_file input(data + "extrabytes.las");
  const auto first = some_normals(input.size(), 1), second = some_normals(input.size(), 2);
  const std::string once = (folder.path / "once.las").string(), twice = (folder.path / "twice.las").string();
  CGAL::RRHT::IO::write_LAS_with_normals(input, once, first.first.data());
  CGAL::RRHT::IO::write_LAS_with_normals(LAS_file(once), twice, second.first.data(), second.second.data());
  const LAS_file output(twice);
  // The confidence is appended; the normals take the same bytes.
  CHECK(output.record_length() == input.record_length() + 32);
  CHECK(output.extra_bytes().size() == input.extra_bytes().size() + 4);
  CHECK(field_of(output, "NormalY")[10] == second.first[3 * 10 + 1]);
  CHECK(field_of(output, "NormalConfidence") == second.second);
  // In place of the input itself.
  CGAL::RRHT::IO::write_LAS_with_normals(LAS_file(twice), twice, first.first.data(), first.second.data());
  CHECK(field_of(LAS_file(twice), "NormalX")[5] == first.first[3 * 5]);
  CHECK(std::distance(fs::directory_iterator(folder.path), fs::directory_iterator()) == 2);
}

TEST_CASE("Extra bytes that no descriptor covers are described before the normals", "[las]")
{
  // simple.las with 5 more bytes in each record and no extra-bytes record.
  const Scratch_folder folder("undocumented");
  std::vector<unsigned char> bytes = bytes_of(data + "simple.las");
  const LAS_file simple(data + "simple.las");
  std::vector<unsigned char> longer(bytes.begin(), bytes.begin() + simple.points_begin());
  set<std::uint16_t>(longer, 105, 39);
  for(std::size_t i = 0; i < simple.size(); ++i)
  {
    const auto record = bytes.begin() + simple.points_begin() + i * 34;
    longer.insert(longer.end(), record, record + 34);
    longer.insert(longer.end(), { 1, 2, 3, 4, 5 });
  }
  const fs::path path = folder.write("longer.las", longer);
  const LAS_file input(path.string());
  CHECK(input.extra_bytes().empty());
  const auto normals = some_normals(input.size(), 3).first;
  CGAL::RRHT::IO::write_LAS_with_normals(input, (folder.path / "out.las").string(), normals.data());
  const LAS_file output((folder.path / "out.las").string());
  REQUIRE(output.extra_bytes().size() == 4);
  CHECK(output.extra_bytes()[0].data_type == 0);
  CHECK(output.extra_bytes()[0].size == 5);
  CHECK(output.extra_bytes()[1].name == "NormalX");
  CHECK(output.extra_bytes()[1].offset == 39);
  CHECK(field_of(output, "NormalZ")[7] == normals[3 * 7 + 2]);
}

TEST_CASE("The extended records after the points are kept, and the offset to them moved", "[las]")
{
  // test1_4.las with one extended record appended.
  const Scratch_folder folder("evlr");
  std::vector<unsigned char> bytes = bytes_of(data + "test1_4.las");
  const std::uint64_t start = bytes.size();
  std::vector<unsigned char> evlr(60 + 11, 0);
  layout::write_text(&evlr[2], "someone", 16);
  set<std::uint16_t>(evlr, 18, 42);
  set<std::uint64_t>(evlr, 20, 11);
  std::memcpy(&evlr[60], "hello world", 11);
  bytes.insert(bytes.end(), evlr.begin(), evlr.end());
  set<std::uint64_t>(bytes, 235, start);
  set<std::uint32_t>(bytes, 243, 1);
  const fs::path path = folder.write("evlr.las", bytes);
  const LAS_file input(path.string());
  REQUIRE(input.records().size() == 3);
  CHECK(input.records().back().extended);
  const auto normals = some_normals(input.size(), 4).first;
  CGAL::RRHT::IO::write_LAS_with_normals(input, (folder.path / "out.las").string(), normals.data());
  const LAS_file output((folder.path / "out.las").string());
  REQUIRE(output.records().size() == 4);
  const CGAL::RRHT::IO::LAS_record& moved = output.records().back();
  CHECK(moved.extended);
  CHECK(moved.user_id == "someone");
  CHECK(moved.length == 11);
  const std::vector<unsigned char> written = bytes_of(folder.path / "out.las");
  CHECK(std::string(written.begin() + moved.begin + 60, written.end()) == "hello world");
}

TEST_CASE("Truncated or inconsistent LAS files are refused, each with what is wrong", "[las]")
{
  const Scratch_folder folder("bad");
  const std::vector<unsigned char> simple = bytes_of(data + "simple.las");
  const std::vector<unsigned char> extra = bytes_of(data + "extrabytes.las");
  auto changed = [&](const std::vector<unsigned char>& bytes, auto change) {
    std::vector<unsigned char> copy = bytes;
    change(copy);
    return folder.write("bad.las", copy).string();
  };
  check_message(changed(simple, [](auto& b) { b.resize(b.size() / 2); }), { "truncated", "1065 point records" });
  check_message(changed(simple, [](auto& b) { b.resize(100); }), { "truncated" });
  check_message(changed(simple, [](auto& b) { b[0] = 'X'; }), { "not a LAS file" });
  check_message(changed(simple, [](auto& b) { set<std::uint16_t>(b, 105, 30); }),
                { "30 bytes", "format 3's 34" });
  check_message(changed(simple, [](auto& b) { b[104] = 11; }), { "point format 11" });
  check_message(changed(simple, [](auto& b) { b[25] = 5; }), { "LAS 1.5" });
  check_message(changed(simple, [](auto& b) { set<std::uint16_t>(b, 94, 200); }),
                { "header size" });
  check_message(changed(simple, [](auto& b) { set<std::uint32_t>(b, 96, 1u << 30); }),
                { "truncated" });
  check_message(changed(simple, [](auto& b) { set<std::uint32_t>(b, 100, 1); }),
                { "variable-length record 1 of 1", "runs into" });
  check_message(changed(simple, [](auto& b) { set<double>(b, 139, 0.); }), { "y scale" });
  check_message(changed(extra, [](auto& b) { set<std::uint16_t>(b, 375 + 20, 959); }),
                { "not a whole number" });
  check_message(changed(extra, [](auto& b) { set<std::uint16_t>(b, 105, 60); }),
                { "more than the 26" });
  check_message(changed(extra, [](auto& b) { b[375 + 54 + 192 + 2] = 31; }), { "reserved data type 31" });
  check_message(changed(extra, [](auto& b) { set<std::uint64_t>(b, 247, 1064); }),
                { "disagree" });
}

TEST_CASE("Seeded fuzz: a damaged LAS file is read or refused, never more", "[las]")
{
  // Random bytes of the header, the records and the first points changed:
  // each file opens, or throws LAS_error; one that opens is read and
  // written back whole.
  const Scratch_folder folder("fuzz");
  std::mt19937 random(20261130);
  int opened = 0, refused = 0;
  for(const std::string name : { "simple.las", "extrabytes.las", "test1_4.las", "simple.laz" })
  {
    const std::vector<unsigned char> original = bytes_of(data + name);
    const std::size_t head = (std::min<std::size_t>)(original.size(), 2500);
    for(int round = 0; round < 150; ++round)
    {
      std::vector<unsigned char> bytes = original;
      const int changes = 1 + int(random() % 4);
      for(int c = 0; c < changes; ++c)
        bytes[random() % head] = static_cast<unsigned char>(random());
      if(random() % 8 == 0)
        bytes.resize(random() % bytes.size());
      const std::string path = folder.write("fuzz.las", bytes).string();
      try
      {
        const LAS_file file(path);
        std::vector<double> xyz(3 * (std::min<std::uint64_t>)(file.size(), 5000));
        file.read_points(0, xyz.size() / 3, xyz.data());
        if(file.size() <= 5000)
        {
          const auto normals = some_normals(file.size(), 5);
          CGAL::RRHT::IO::write_LAS_with_normals(file, (folder.path / "out.las").string(), normals.first.data(),
                                                 normals.second.data());
          CHECK(LAS_file((folder.path / "out.las").string()).size() == file.size());
        }
        ++opened;
      }
      catch(const LAS_error&)
      {
        ++refused;
      }
    }
  }
  INFO("opened " << opened << ", refused " << refused);
  CHECK(opened > 50);
  CHECK(refused > 50);
}
