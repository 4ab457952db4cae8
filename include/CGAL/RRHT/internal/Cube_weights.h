// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The weights of the small cubes of RRHT_Cubes (paper, Section 5, Fig. 5).

#ifndef CGAL_RRHT_INTERNAL_CUBE_WEIGHTS_H
#define CGAL_RRHT_INTERNAL_CUBE_WEIGHTS_H

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Squared distance from the origin (the center of B_P) to the cube
/// [low[0], low[0] + side] x [low[1], ...] x [low[2], ...]; 0 inside.
inline double squared_distance_to_cube(const double low[3], double side)
{
  double squared_distance = 0;
  for(int d = 0; d < 3; ++d)
  {
    const double gap = (std::max)({ low[d], -(low[d] + side), 0. });
    squared_distance += gap * gap;
  }
  return squared_distance;
}
/// Weights of the c^3 small cubes that cover the ball (paper, Fig. 5): the
/// fraction of each cube's volume inside the ball. They depend on c only
/// (the ball is scaled to the unit ball) and are computed once, by the
/// midpoint rule on m^3 sub-cubes per cube (m = max(8, 128 / c), i.e. 32^3
/// for c = 4). A cube that meets the ball always keeps a positive weight, so
/// that every point of the neighborhood can be drawn.
class Cube_weights
{
public:
  explicit Cube_weights(unsigned int c) : m_c(c), m_weights(std::size_t(c) * c * c, 0.)
  {
    const unsigned int m = (std::max)(8u, 128u / c);
    const double side = 2. / c, sub = side / m;
    for(unsigned int i = 0; i < c; ++i)
      for(unsigned int j = 0; j < c; ++j)
        for(unsigned int k = 0; k < c; ++k)
        {
          const double lo[3] = { -1 + i * side, -1 + j * side, -1 + k * side };
          if(squared_distance_to_cube(lo, side) >= 1)
            continue;
          std::size_t inside = 0;
          for(unsigned int a = 0; a < m; ++a)
            for(unsigned int b = 0; b < m; ++b)
              for(unsigned int e = 0; e < m; ++e)
              {
                const double x = lo[0] + (a + 0.5) * sub, y = lo[1] + (b + 0.5) * sub, z = lo[2] + (e + 0.5) * sub;
                inside += (x * x + y * y + z * z <= 1);
              }
          m_weights[(std::size_t(i) * c + j) * c + k] = (std::max)(double(inside), 0.5) / (double(m) * m * m);
        }
  }

  unsigned int cubes_per_axis() const { return m_c; }
  double weight(std::uint64_t cube) const { return m_weights[cube]; }

private:
  unsigned int m_c;
  std::vector<double> m_weights;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CUBE_WEIGHTS_H
