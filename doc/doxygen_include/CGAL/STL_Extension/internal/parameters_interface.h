// Doxygen only (doc/Doxyfile's INCLUDE_PATH), never compiled: an empty
// stand-in for CGAL's list of named parameters, which
// CGAL/RRHT/parameters.h includes inside a class and a namespace to generate
// one member function per named parameter of CGAL. The reference describes
// these functions in prose; without this file Doxygen warns that the include
// file is not found.
