// A compile-time check that a serialiser lists every field of a struct: fieldCount<N>(v)
// compiles only when v's type has exactly N data members (a structured binding of N names),
// so adding a member to a struct without adding it to its field list is a build error at the
// list (src/model/serialize.cpp).
#pragma once

#include <cstddef>

namespace crumple::util {

template <std::size_t N, class T>
constexpr void fieldCount(const T& v) {
  static_assert(N >= 1 && N <= 32, "fieldCount: between 1 and 32 members");
  if constexpr (N == 1) {
    [[maybe_unused]] const auto& [m0] = v;
  } else if constexpr (N == 2) {
    [[maybe_unused]] const auto& [m0, m1] = v;
  } else if constexpr (N == 3) {
    [[maybe_unused]] const auto& [m0, m1, m2] = v;
  } else if constexpr (N == 4) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3] = v;
  } else if constexpr (N == 5) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4] = v;
  } else if constexpr (N == 6) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5] = v;
  } else if constexpr (N == 7) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6] = v;
  } else if constexpr (N == 8) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7] = v;
  } else if constexpr (N == 9) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8] = v;
  } else if constexpr (N == 10) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9] = v;
  } else if constexpr (N == 11) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10] = v;
  } else if constexpr (N == 12) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11] = v;
  } else if constexpr (N == 13) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12] = v;
  } else if constexpr (N == 14) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13] = v;
  } else if constexpr (N == 15) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14] =
        v;
  } else if constexpr (N == 16) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15] = v;
  } else if constexpr (N == 17) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16] = v;
  } else if constexpr (N == 18) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17] = v;
  } else if constexpr (N == 19) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18] = v;
  } else if constexpr (N == 20) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19] = v;
  } else if constexpr (N == 21) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20] = v;
  } else if constexpr (N == 22) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21] = v;
  } else if constexpr (N == 23) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22] = v;
  } else if constexpr (N == 24) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23] = v;
  } else if constexpr (N == 25) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24] = v;
  } else if constexpr (N == 26) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25] = v;
  } else if constexpr (N == 27) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26] = v;
  } else if constexpr (N == 28) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27] =
        v;
  } else if constexpr (N == 29) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27,
                                  m28] = v;
  } else if constexpr (N == 30) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27,
                                  m28, m29] = v;
  } else if constexpr (N == 31) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27,
                                  m28, m29, m30] = v;
  } else if constexpr (N == 32) {
    [[maybe_unused]] const auto& [m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14,
                                  m15, m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27,
                                  m28, m29, m30, m31] = v;
  }
}

}  // namespace crumple::util
