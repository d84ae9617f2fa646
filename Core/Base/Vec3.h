#pragma once
#include <cmath>

#include "Base/HostDevice.h"

namespace soak {

// fmaxf and fminf, but inline on the CPU too: GCC calls libm for them (the
// IEEE rules for NaN and signed zero keep it from using maxss), and the
// neighbour count spent 12 % of its CPU time in those calls. Same results as
// fmaxf/fminf, NaN included: a NaN argument gives the other one.
SOAK_INLINE float maxf(float a, float b) {
#if defined(__CUDA_ARCH__)
  return fmaxf(a, b);
#else
  return (a > b || b != b) ? a : b;
#endif
}
SOAK_INLINE float minf(float a, float b) {
#if defined(__CUDA_ARCH__)
  return fminf(a, b);
#else
  return (a < b || b != b) ? a : b;
#endif
}

// Plain float vector usable on host and device.
struct Vec3 {
  float x = 0.f, y = 0.f, z = 0.f;
  Vec3() = default;
  SOAK_HD constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
};

// Position plus inverse mass (w), 16-byte aligned for one vector load.
struct alignas(16) Float4 {
  float x = 0.f, y = 0.f, z = 0.f, w = 0.f;
  Float4() = default;
  SOAK_HD constexpr Float4(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
  SOAK_HD constexpr Float4(const Vec3& v, float w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
  SOAK_HD constexpr Vec3 xyz() const { return Vec3(x, y, z); }
};

SOAK_INLINE Vec3 operator+(Vec3 a, Vec3 b) { return Vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
SOAK_INLINE Vec3 operator-(Vec3 a, Vec3 b) { return Vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
SOAK_INLINE Vec3 operator-(Vec3 a) { return Vec3(-a.x, -a.y, -a.z); }
SOAK_INLINE Vec3 operator*(Vec3 a, float s) { return Vec3(a.x * s, a.y * s, a.z * s); }
SOAK_INLINE Vec3 operator*(float s, Vec3 a) { return Vec3(a.x * s, a.y * s, a.z * s); }
SOAK_INLINE Vec3 operator/(Vec3 a, float s) { return Vec3(a.x / s, a.y / s, a.z / s); }
SOAK_INLINE Vec3& operator+=(Vec3& a, Vec3 b) { a.x += b.x; a.y += b.y; a.z += b.z; return a; }
SOAK_INLINE Vec3& operator-=(Vec3& a, Vec3 b) { a.x -= b.x; a.y -= b.y; a.z -= b.z; return a; }
SOAK_INLINE Vec3& operator*=(Vec3& a, float s) { a.x *= s; a.y *= s; a.z *= s; return a; }
SOAK_INLINE float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
SOAK_INLINE Vec3 cross(Vec3 a, Vec3 b) {
  return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
SOAK_INLINE float lengthSquared(Vec3 a) { return dot(a, a); }
SOAK_INLINE float length(Vec3 a) { return sqrtf(dot(a, a)); }
SOAK_INLINE Vec3 minVec(Vec3 a, Vec3 b) { return Vec3(minf(a.x, b.x), minf(a.y, b.y), minf(a.z, b.z)); }
SOAK_INLINE Vec3 maxVec(Vec3 a, Vec3 b) { return Vec3(maxf(a.x, b.x), maxf(a.y, b.y), maxf(a.z, b.z)); }
SOAK_INLINE bool isFinite(float v) {
#if defined(__CUDA_ARCH__)
  return isfinite(v);
#else
  return std::isfinite(v);
#endif
}
SOAK_INLINE bool isFinite(Vec3 a) { return isFinite(a.x) && isFinite(a.y) && isFinite(a.z); }
SOAK_INLINE bool isZero(Vec3 a) { return a.x == 0.f && a.y == 0.f && a.z == 0.f; }
// Unit vector, or zero for a (near) zero vector.
SOAK_INLINE Vec3 normalizedOrZero(Vec3 a) {
  float l = length(a);
  return l > 1e-20f ? a / l : Vec3(0.f, 0.f, 0.f);
}

}  // namespace soak
