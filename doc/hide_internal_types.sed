# Doxygen input filter (doc/Doxyfile's FILTER_PATTERNS), for the reference
# only: the compiled headers are not changed. A public signature that names a
# type of an internal namespace shows `unspecified_type` instead, as in CGAL's
# reference; its documentation says what the type is. Lines are replaced one
# for one, so that Doxygen's line numbers stay right.
# CGAL/RRHT/parameters.h, the return type of CGAL::RRHT::parameters::extend():
s/^typename internal::Extended<.*>::type$/unspecified_type/
