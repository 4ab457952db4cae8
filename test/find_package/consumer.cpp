// Estimates the normals of a small plane with the installed package.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/rrht_estimate_normals.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef std::pair<Kernel::Point_3, Kernel::Vector_3> Point_with_normal;

int main()
{
  if(std::strcmp(CGAL_VERSION_STR, EXPECTED_CGAL_VERSION) != 0)
  {
    std::cerr << "compiled against the headers of CGAL " << CGAL_VERSION_STR << ", expected "
              << EXPECTED_CGAL_VERSION << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<Point_with_normal> points;
  for(int i = 0; i < 20; ++i)
    for(int j = 0; j < 20; ++j)
      points.emplace_back(Kernel::Point_3(i + 0.01 * j * j, j + 0.03 * i, 0), CGAL::NULL_VECTOR);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    points, 20,
    CGAL::RRHT::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>())
      .number_of_planes(100));
  for(const Point_with_normal& pn : points)
    if(!(std::abs(std::abs(pn.second.z()) - 1) < 1e-9))
    {
      std::cerr << "wrong normal " << pn.second << std::endl;
      return EXIT_FAILURE;
    }
  std::cout << "find_package(CGAL_RRHT) with CGAL " << CGAL_VERSION_STR << ": " << points.size() << " normals estimated" << std::endl;
  return EXIT_SUCCESS;
}
