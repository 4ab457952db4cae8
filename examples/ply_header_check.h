// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A check of a PLY file's header before CGAL's PLY reader sees it, shared by
// the examples that read a user's files.

#ifndef CGAL_RRHT_EXAMPLES_PLY_HEADER_CHECK_H
#define CGAL_RRHT_EXAMPLES_PLY_HEADER_CHECK_H

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// What makes a PLY header one that CGAL's PLY reader (5.5 to 6.2) cannot
// take, or an empty string. That reader adds each property line's property
// to the last element read: a damaged header whose properties come before
// any element makes it write through an empty list and crash. And it reads
// the points of every `vertex` element, at the origin where an element has
// no x, y and z: a damaged header with two, or without the coordinates,
// would add points that the file does not hold. It reads the first line as
// the signature and the second as the format, refusing them itself, and
// keywords from the third line on, up to end_header.
inline std::string damaged_ply_header(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool any_element = false, has_vertex = false, in_vertex = false;
  std::vector<std::string> vertex_properties;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::string keyword, first, second;
    words >> keyword >> first >> second;
    if(number == 1 && keyword != "ply")
      return {}; // not a PLY file: CGAL refuses it
    if(number <= 2)
      continue;
    const auto at_line = [number](const std::string& what) {
      return what + ", line " + std::to_string(number) + " of the PLY header";
    };
    if(keyword == "end_header")
      break;
    if(keyword == "element")
    {
      in_vertex = (first == "vertex");
      if(in_vertex && has_vertex)
        return at_line("a second vertex element");
      any_element = true;
      has_vertex = has_vertex || in_vertex;
    }
    else if(keyword == "property")
    {
      if(!any_element)
        return at_line("a property before any element");
      if(in_vertex)
        vertex_properties.push_back(second);
    }
  }
  const auto has = [&](const char* name) {
    return std::find(vertex_properties.begin(), vertex_properties.end(), name) != vertex_properties.end();
  };
  if(has_vertex && !(has("x") && has("y") && has("z")))
    return "the vertices have no x, y and z properties";
  return {};
}

#endif // CGAL_RRHT_EXAMPLES_PLY_HEADER_CHECK_H
