// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of `CGAL::rrht_estimate_normals()`.

#ifndef CGAL_RRHT_PARAMETERS_H
#define CGAL_RRHT_PARAMETERS_H

#include <CGAL/RRHT/Setting.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <functional>
#include <type_traits>

namespace CGAL {
namespace RRHT {

/// \cond SKIP_IN_MANUAL
namespace internal_np {
// One tag type per RRHT parameter. They live outside `CGAL::internal_np`, which
// a package outside CGAL cannot extend, but `CGAL::parameters::get_parameter()`
// finds them in a chain like any CGAL tag.
#define CGAL_RRHT_NAMED_PARAMETERS(X)                          \
  X(number_of_planes_t, number_of_planes)                      \
  X(accumulator_slices_t, accumulator_slices)                  \
  X(number_of_rotations_t, number_of_rotations)                \
  X(use_confidence_interval_t, use_confidence_interval)        \
  X(sampling_t, sampling)                                      \
  X(presampling_factor_t, presampling_factor)                  \
  X(aggregation_t, aggregation)                                \
  X(cluster_angle_t, cluster_angle)                            \
  X(confidence_map_t, confidence_map)                          \
  X(setting_t, setting)                                        \
  X(refit_t, refit)                                            \
  X(point_id_map_t, point_id_map)                              \
  X(support_radius_map_t, support_radius_map)                  \
  X(neighbor_only_map_t, neighbor_only_map)                    \
  X(direction_t, direction)                                    \
  X(viewpoint_t, viewpoint)                                    \
  X(viewpoint_map_t, viewpoint_map)

// The switches that `setting` replaces, kept for one release: their tags
// stay, so that the estimation reads them, and their chain functions go
// with CGAL_NO_DEPRECATED_CODE.
#define CGAL_RRHT_DEPRECATED_NAMED_PARAMETERS(X)               \
  X(least_squares_first_t, least_squares_first)                \
  X(adaptive_t, adaptive)

#define CGAL_RRHT_DECLARE_TAG(TAG, NAME) enum TAG { NAME };
CGAL_RRHT_NAMED_PARAMETERS(CGAL_RRHT_DECLARE_TAG)
CGAL_RRHT_DEPRECATED_NAMED_PARAMETERS(CGAL_RRHT_DECLARE_TAG)
#undef CGAL_RRHT_DECLARE_TAG
} // namespace internal_np
/// \endcond

/// \ingroup PkgRRHTRef
/// A chain of named parameters that accepts both the named parameters of
/// \cgal (`point_map`, `normal_map`, `neighbor_radius`, ...) and those of
/// RRHT (`number_of_planes`, `sampling`, ...), in any order.
///
/// It *is* a `CGAL::Named_function_parameters`: every function of \cgal that
/// takes named parameters reads it unchanged, and ignores the RRHT entries.
/// Only the member functions differ, each returning this type again so that
/// the chain goes on. A chain is started from `CGAL::RRHT::parameters`.
///
/// Besides `combine()`, it has one member function per named parameter,
/// named after it and taking its value, which appends that parameter:
/// - one per named parameter of \cgal (`point_map()`, `normal_map()`,
///   `neighbor_radius()`, `callback()`, `random_seed()`, `geom_traits()`, ...,
///   all those of the \cgal version in use);
/// - one per named parameter of RRHT: `number_of_planes()`,
///   `accumulator_slices()`, `number_of_rotations()`,
///   `use_confidence_interval()`, `sampling()`, `presampling_factor()`,
///   `aggregation()`, `cluster_angle()`, `confidence_map()`, `setting()`, `refit()`,
///   `point_id_map()`, `support_radius_map()` and `neighbor_only_map()`, and
///   those of `CGAL::rrht_orient_normals()`: `direction()`, `viewpoint()` and
///   `viewpoint_map()`;
/// - the deprecated `least_squares_first()` and `adaptive()`, which `setting()`
///   replaces (not with `CGAL_NO_DEPRECATED_CODE`).
///
/// The parameters that `CGAL::rrht_estimate_normals()` reads, their types
/// and their defaults are listed in its documentation.
///
/// \tparam T the type of the value of the last parameter of the chain
/// \tparam Tag the tag of the last parameter of the chain
/// \tparam Base the rest of the chain
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters
  : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : Cgal_parameters() {}
  Named_function_parameters(const T& v) : Cgal_parameters(v) {}
  Named_function_parameters(const T& v, const Base& b) : Cgal_parameters(v, b) {}
  /// \endcond

  // CGAL's parameters, generated from CGAL's own list so that none is
  // missing, whatever the version: CGAL 5.6 and later also list parameters
  // held by reference (`_cref_only`, `_ref_only`) and parameters kept for
  // compatibility with Boost's syntax, which are members like the others.
#define CGAL_RRHT_MEMBER_BY_VALUE(X, Y, Z)                                      \
  template <typename K>                                                         \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const  \
  {                                                                             \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);  \
  }
#define CGAL_RRHT_MEMBER_BY_REFERENCE(X, Y, Z, CONST, WRAP)                     \
  template <typename K>                                                         \
  Named_function_parameters<std::reference_wrapper<CONST K>, CGAL::internal_np::X, self> Z(CONST K& k) const \
  {                                                                             \
    return Named_function_parameters<std::reference_wrapper<CONST K>, CGAL::internal_np::X, self>(WRAP(k), *this); \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_RRHT_MEMBER_BY_VALUE(X, Y, Z)
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) CGAL_RRHT_MEMBER_BY_VALUE(X, Y, Z)
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) CGAL_RRHT_MEMBER_BY_VALUE(X, Y, Z)
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z) CGAL_RRHT_MEMBER_BY_REFERENCE(X, Y, Z, const, std::cref)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z) CGAL_RRHT_MEMBER_BY_REFERENCE(X, Y, Z, , std::ref)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_extra_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#undef CGAL_RRHT_MEMBER_BY_VALUE
#undef CGAL_RRHT_MEMBER_BY_REFERENCE

  /// Appends the parameter of the one-parameter chain `np`, as
  /// `CGAL::Named_function_parameters::combine()` of \cgal 6 does, and stays
  /// an RRHT chain.
  /// \param np a chain of one named parameter, e.g. `CGAL::parameters::point_map(pm)`
  /// \return this chain followed by the parameter of `np`
  template <typename OT, typename OTag>
  Named_function_parameters<OT, OTag, self> combine(const CGAL::Named_function_parameters<OT, OTag>& np) const
  {
    return Named_function_parameters<OT, OTag, self>(CGAL::internal_np::get_reference(np.v), *this);
  }

  /// Appends the parameters of the one-parameter chains `np` and `nps`, in
  /// this order, as `CGAL::Named_function_parameters::combine()` of \cgal 6
  /// does, and stays an RRHT chain.
  /// \param np a chain of one named parameter
  /// \param nps more chains of one named parameter each
  /// \return this chain followed by the parameters of `np` and `nps`
  template <typename OT, typename OTag, typename... NPS>
  auto combine(const CGAL::Named_function_parameters<OT, OTag>& np, const NPS&... nps) const
  {
    return combine(np).combine(nps...);
  }

  // RRHT's parameters.
#define CGAL_RRHT_MEMBER(TAG, NAME)                                             \
  template <typename K>                                                         \
  Named_function_parameters<K, internal_np::TAG, self> NAME(const K& k) const   \
  {                                                                             \
    return Named_function_parameters<K, internal_np::TAG, self>(k, *this);      \
  }
  CGAL_RRHT_NAMED_PARAMETERS(CGAL_RRHT_MEMBER)
#ifndef CGAL_NO_DEPRECATED_CODE
  CGAL_RRHT_DEPRECATED_NAMED_PARAMETERS(CGAL_RRHT_MEMBER)
#endif
#undef CGAL_RRHT_MEMBER
};

/// The starting points of RRHT named-parameter chains: every function of
/// `CGAL::parameters`, and one per RRHT parameter. For example
/// \code
/// namespace params = CGAL::RRHT::parameters;
/// params::point_map(pm).normal_map(nm).number_of_planes(300).sampling(CGAL::RRHT::Sampling::CUBES)
/// params::sampling(CGAL::RRHT::Sampling::CUBES).neighbor_radius(0.1).normal_map(nm)
/// params::extend(np).number_of_rotations(2)   // np: any CGAL named-parameter chain
/// params::setting(CGAL::RRHT::Setting::PAPER_FAST).point_map(pm).normal_map(nm)   // the paper's fast setting
/// \endcode
///
/// Each of these functions is named after a named parameter, takes its value
/// and returns a `CGAL::RRHT::Named_function_parameters` that holds it:
/// one per named parameter of \cgal (`point_map()`, `normal_map()`,
/// `neighbor_radius()`, ...) and one per named parameter of RRHT
/// (`number_of_planes()`, `accumulator_slices()`, `number_of_rotations()`,
/// `use_confidence_interval()`, `sampling()`, `presampling_factor()`,
/// `aggregation()`, `cluster_angle()`, `confidence_map()`, `setting()`, `refit()`,
/// `point_id_map()`, `support_radius_map()`, `neighbor_only_map()`,
/// `direction()`, `viewpoint()`, `viewpoint_map()`), and the deprecated
/// `least_squares_first()`, `adaptive()`, `paper_precise()` and `paper_fast()`.
/// \ingroup PkgRRHTRef
namespace parameters {

/// The type of an empty chain, `default_values()`.
typedef RRHT::Named_function_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;

/// An empty chain, to be continued with any parameter.
/// \return a chain that holds no parameter
inline Default_named_parameters default_values() { return Default_named_parameters(); }

#define CGAL_RRHT_FUNCTION_BY_VALUE(X, Y, Z)                                    \
  template <typename K>                                                         \
  RRHT::Named_function_parameters<K, CGAL::internal_np::X> Z(const K& p)        \
  {                                                                             \
    return RRHT::Named_function_parameters<K, CGAL::internal_np::X>(p);         \
  }
#define CGAL_RRHT_FUNCTION_BY_REFERENCE(X, Y, Z, CONST, WRAP)                   \
  template <typename K>                                                         \
  RRHT::Named_function_parameters<std::reference_wrapper<CONST K>, CGAL::internal_np::X> Z(CONST K& p) \
  {                                                                             \
    return RRHT::Named_function_parameters<std::reference_wrapper<CONST K>, CGAL::internal_np::X>(WRAP(p)); \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_RRHT_FUNCTION_BY_VALUE(X, Y, Z)
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) CGAL_RRHT_FUNCTION_BY_VALUE(X, Y, Z)
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) CGAL_RRHT_FUNCTION_BY_VALUE(X, Y, Z)
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z) CGAL_RRHT_FUNCTION_BY_REFERENCE(X, Y, Z, const, std::cref)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z) CGAL_RRHT_FUNCTION_BY_REFERENCE(X, Y, Z, , std::ref)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_extra_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#undef CGAL_RRHT_FUNCTION_BY_VALUE
#undef CGAL_RRHT_FUNCTION_BY_REFERENCE

#define CGAL_RRHT_FREE_FUNCTION(TAG, NAME)                                      \
  template <typename K>                                                         \
  RRHT::Named_function_parameters<K, RRHT::internal_np::TAG> NAME(const K& p)   \
  {                                                                             \
    return RRHT::Named_function_parameters<K, RRHT::internal_np::TAG>(p);       \
  }
CGAL_RRHT_NAMED_PARAMETERS(CGAL_RRHT_FREE_FUNCTION)
#ifndef CGAL_NO_DEPRECATED_CODE
CGAL_RRHT_DEPRECATED_NAMED_PARAMETERS(CGAL_RRHT_FREE_FUNCTION)
#endif
#undef CGAL_RRHT_FREE_FUNCTION
#undef CGAL_RRHT_NAMED_PARAMETERS
#undef CGAL_RRHT_DEPRECATED_NAMED_PARAMETERS

#ifndef CGAL_NO_DEPRECATED_CODE
/// \cond SKIP_IN_MANUAL
typedef RRHT::Named_function_parameters<Setting, RRHT::internal_np::setting_t> Setting_parameters;
/// \endcond

/// \deprecated Use `setting(CGAL::RRHT::Setting::PAPER_PRECISE)`, which this returns.
/// \return a chain that holds the paper's precise setting
CGAL_DEPRECATED_MSG("use setting(CGAL::RRHT::Setting::PAPER_PRECISE)")
inline Setting_parameters paper_precise() { return setting(Setting::PAPER_PRECISE); }

/// \deprecated Use `setting(CGAL::RRHT::Setting::PAPER_FAST)`, which this returns.
/// \return a chain that holds the paper's fast setting
CGAL_DEPRECATED_MSG("use setting(CGAL::RRHT::Setting::PAPER_FAST)")
inline Setting_parameters paper_fast() { return setting(Setting::PAPER_FAST); }
#endif

/// \cond SKIP_IN_MANUAL
namespace internal {
// Rebuilds a chain, link by link, as an RRHT chain holding the same values.
template <typename Chain> struct Extended;

template <> struct Extended<CGAL::internal_np::No_property>
{
  typedef CGAL::internal_np::No_property type;
};

template <typename T, typename Tag, typename Base>
struct Extended<CGAL::Named_function_parameters<T, Tag, Base> >
{
  typedef Extended<Base> Tail;
  typedef RRHT::Named_function_parameters<T, Tag, typename Tail::type> type;

  static type make(const CGAL::Named_function_parameters<T, Tag, Base>& link)
  {
    return make(link, std::is_same<Base, CGAL::internal_np::No_property>());
  }
  static type make(const CGAL::Named_function_parameters<T, Tag, Base>& link, std::true_type /*last link*/)
  {
    return type(CGAL::internal_np::get_reference(link.v));
  }
  static type make(const CGAL::Named_function_parameters<T, Tag, Base>& link, std::false_type)
  {
    return type(CGAL::internal_np::get_reference(link.v), Tail::make(static_cast<const Base&>(link)));
  }
};

// An RRHT link is rebuilt like the CGAL link it derives from.
template <typename T, typename Tag, typename Base>
struct Extended<RRHT::Named_function_parameters<T, Tag, Base> >
  : Extended<CGAL::Named_function_parameters<T, Tag, Base> >
{};
} // namespace internal
/// \endcond

/// Continues an existing chain of \cgal named parameters with RRHT ones. For
/// example, `CGAL::RRHT::parameters::extend(np).number_of_planes(300)` in a
/// function that received `np` from its caller.
/// \param np a chain of \cgal named parameters (or an RRHT chain)
/// \return a `CGAL::RRHT::Named_function_parameters` holding the same
///         parameters as `np`, in the same order
template <typename T, typename Tag, typename Base>
typename internal::Extended<CGAL::Named_function_parameters<T, Tag, Base> >::type
extend(const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return internal::Extended<CGAL::Named_function_parameters<T, Tag, Base> >::make(np);
}

} // namespace parameters
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_PARAMETERS_H
