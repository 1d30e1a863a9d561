// The ray tracer's scene and its kernel: one line of the image, traced as an occam PROC would trace
// it (primary ray, nearest of the spheres and the ground plane, diffuse shading with a shadow ray,
// mirror reflections up to a depth). Written once, templated on the scalar: with float it is the
// sequential reference, with t800sim::Real32 it is recorded as it computes and timed from the T800
// code it compiles to. A line's cost follows what its rays hit -- sky is cheap, a reflecting sphere
// dear -- so the work per item varies, deterministically.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "t800sim/kernel.hpp"

namespace raytrace {

struct Sphere {
  float x, y, z, radius;
  float red, green, blue;
  float reflect;  // share of the colour taken from the mirror ray
};

// Five spheres over a ground plane (y = -1), seen from the origin looking along +z through a
// screen at z = 1 spanning x in [-1, 1] and y in [-0.75, 0.75].
inline const std::array<Sphere, 5> kSpheres = {{
    {0.0f, 0.0f, 5.0f, 1.0f, 0.9f, 0.2f, 0.2f, 0.3f},
    {-2.0f, -0.3f, 6.0f, 0.7f, 0.2f, 0.8f, 0.3f, 0.0f},
    {2.0f, 0.2f, 7.0f, 1.2f, 0.3f, 0.4f, 0.9f, 0.5f},
    {0.8f, -0.7f, 3.5f, 0.3f, 0.9f, 0.8f, 0.2f, 0.0f},
    {-0.8f, 1.2f, 8.0f, 0.8f, 0.8f, 0.8f, 0.8f, 0.6f},
}};
constexpr float kGroundY = -1.0f;
constexpr float kGround[3] = {0.6f, 0.6f, 0.55f};
constexpr float kAmbient = 0.15f;
// A hit nearer than this to a ray's origin is the surface the ray leaves.
constexpr float kEpsilon = 1e-3f;
constexpr float kFar = 1e30f;
// The light's direction, normalised: (-1, 2, -1) / sqrt(6).
constexpr float kLight[3] = {-0.40824829f, 0.81649658f, -0.40824829f};
constexpr int kColours = 3;

// The plain value of a scalar as a float (the float a Real32 computed; a REAL64's rounded).
template <class S>
float plain(const S& x) {
  if constexpr (std::is_floating_point_v<S>)
    return float(x);
  else
    return float(x.value());
}

// What the PROC is given: the scene's arrays (in the worker's memory, loaded once) and the screen
// y of every line (occam would convert the line number; a table costs a load).
template <class S>
struct SceneArrays {
  std::vector<S> x, y, z, radius2, inverse_radius, red, green, blue, reflect, line_v;

  SceneArrays(int width, int height) {
    for (const Sphere& s : kSpheres) {
      x.push_back(s.x);
      y.push_back(s.y);
      z.push_back(s.z);
      radius2.push_back(s.radius * s.radius);
      inverse_radius.push_back(1.0f / s.radius);
      red.push_back(s.red);
      green.push_back(s.green);
      blue.push_back(s.blue);
      reflect.push_back(s.reflect);
    }
    const float half_height = 0.75f;
    const float step = 2.0f / float(width);  // square pixels
    for (int line = 0; line < height; ++line)
      line_v.push_back(half_height - (float(line) + 0.5f) * step);
  }

  void declare() {
    t800sim::declare(x, "sphere.x");
    t800sim::declare(y, "sphere.y");
    t800sim::declare(z, "sphere.z");
    t800sim::declare(radius2, "sphere.r2");
    t800sim::declare(inverse_radius, "sphere.inv.r");
    t800sim::declare(red, "sphere.red");
    t800sim::declare(green, "sphere.green");
    t800sim::declare(blue, "sphere.blue");
    t800sim::declare(reflect, "sphere.reflect");
    t800sim::declare(line_v, "line.v");
  }
};

template <class S>
struct Vec {
  S x, y, z;
};

template <class S>
S dot(const Vec<S>& a, const Vec<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// The nearest hit along o + t d (t > kEpsilon): a sphere's index, the number of spheres for the
// ground plane, -1 for none.
template <class S>
struct Hit {
  int what = -1;
  S t = S(kFar);
};

template <class S>
class Tracer {
 public:
  Tracer(SceneArrays<S>& scene, int reflections) : s_(scene), reflections_(reflections) {}

  // Traces line `line` of a width-pixel image into rgb: red plane, green plane, blue plane.
  void line(int line, int width, std::vector<S>& rgb) {
    using t800sim::seq;
    const S step = S(2.0f / float(width));
    S u;
    t800sim::declare_variable(u, "u");
    u = S(-1.0f) + S(0.5f) * step;
    const S v = s_.line_v[std::size_t(line)];
    for (std::size_t px : seq<S>(std::size_t(width))) {
      using std::sqrt;
      const S length = sqrt(u * u + v * v + S(1.0f));
      const S inverse = S(1.0f) / length;
      const Vec<S> d{u * inverse, v * inverse, inverse};
      const Vec<S> colour = trace({S(0.0f), S(0.0f), S(0.0f)}, d, 0);
      rgb[px] = colour.x;
      rgb[std::size_t(width) + px] = colour.y;
      rgb[2 * std::size_t(width) + px] = colour.z;
      u = u + step;
    }
  }

 private:
  static constexpr int kPlane = int(std::tuple_size_v<decltype(kSpheres)>);

  void integer_move() { t800sim::integer<S>(t800sim::IntegerStatement::move); }
  void integer_test() { t800sim::integer<S>(t800sim::IntegerStatement::test); }

  Hit<S> nearest(const Vec<S>& o, const Vec<S>& d) {
    using std::sqrt;
    Hit<S> hit;
    for (std::size_t k : t800sim::seq<S>(s_.x.size())) {
      const Vec<S> oc{o.x - s_.x[k], o.y - s_.y[k], o.z - s_.z[k]};
      const S b = dot(oc, d);
      const S c = dot(oc, oc) - s_.radius2[k];
      const S discriminant = b * b - c;
      if (discriminant > S(0.0f)) {
        const S t = -b - sqrt(discriminant);
        if (t > S(kEpsilon)) {
          if (t < hit.t) {
            hit.t = t;
            hit.what = int(k);
            integer_move();
          }
        }
      }
    }
    if (d.y < S(0.0f)) {
      const S t = (S(kGroundY) - o.y) / d.y;
      if (t > S(kEpsilon)) {
        if (t < hit.t) {
          hit.t = t;
          hit.what = kPlane;
          integer_move();
        }
      }
    }
    return hit;
  }

  // Whether anything lies between p and the light (every sphere tested, as a SEQ would).
  bool shadowed(const Vec<S>& p) {
    using std::sqrt;
    const Vec<S> l{S(kLight[0]), S(kLight[1]), S(kLight[2])};
    bool blocked = false;
    for (std::size_t k : t800sim::seq<S>(s_.x.size())) {
      const Vec<S> oc{p.x - s_.x[k], p.y - s_.y[k], p.z - s_.z[k]};
      const S b = dot(oc, l);
      const S c = dot(oc, oc) - s_.radius2[k];
      const S discriminant = b * b - c;
      if (discriminant > S(0.0f)) {
        if (-b - sqrt(discriminant) > S(kEpsilon)) {
          blocked = true;
          integer_move();
        }
      }
    }
    return blocked;
  }

  Vec<S> sky(const Vec<S>& d) const {
    return {S(0.35f) + S(0.3f) * d.y, S(0.55f) + S(0.3f) * d.y, S(0.9f) + S(0.1f) * d.y};
  }

  Vec<S> trace(const Vec<S>& o, const Vec<S>& d, int depth) {
    const Hit<S> hit = nearest(o, d);
    integer_test();  // IF hit = none
    if (hit.what < 0) return sky(d);
    const Vec<S> p{o.x + hit.t * d.x, o.y + hit.t * d.y, o.z + hit.t * d.z};
    Vec<S> n{S(0.0f), S(1.0f), S(0.0f)};
    Vec<S> albedo{S(kGround[0]), S(kGround[1]), S(kGround[2])};
    S reflect = S(0.0f);
    integer_test();  // IF hit = plane
    if (hit.what != kPlane) {
      const std::size_t k = std::size_t(hit.what);
      const S inverse_radius = s_.inverse_radius[k];
      n = {(p.x - s_.x[k]) * inverse_radius, (p.y - s_.y[k]) * inverse_radius,
           (p.z - s_.z[k]) * inverse_radius};
      albedo = {s_.red[k], s_.green[k], s_.blue[k]};
      reflect = s_.reflect[k];
    }
    const Vec<S> l{S(kLight[0]), S(kLight[1]), S(kLight[2])};
    S light = S(kAmbient);
    const S diffuse = dot(n, l);
    if (diffuse > S(0.0f)) {
      const bool dark = shadowed(p);
      integer_test();  // IF shadowed
      if (!dark) light = light + diffuse;
    }
    Vec<S> colour{albedo.x * light, albedo.y * light, albedo.z * light};
    integer_test();  // IF depth < reflections AND reflect > 0.0 (AND stops at a false operand)
    if (depth < reflections_ && reflect > S(0.0f)) {
      const S twice = S(2.0f) * dot(d, n);
      const Vec<S> r{d.x - twice * n.x, d.y - twice * n.y, d.z - twice * n.z};
      const Vec<S> mirror = trace(p, r, depth + 1);
      const S keep = S(1.0f) - reflect;
      colour = {keep * colour.x + reflect * mirror.x, keep * colour.y + reflect * mirror.y,
                keep * colour.z + reflect * mirror.z};
    }
    return colour;
  }

  SceneArrays<S>& s_;
  int reflections_;
};

// Line `line` of a width x height image, with scalar S: the colours (red plane, green plane, blue
// plane) as floats. Under a t800sim::record_kernel<Real32> it is recorded as it computes.
template <class S>
std::vector<float> trace_line(int line, int width, int height, int reflections) {
  SceneArrays<S> scene(width, height);
  scene.declare();
  std::vector<S> rgb(std::size_t(kColours * width), S(0.0f));
  t800sim::declare(rgb, "rgb");
  Tracer<S>(scene, reflections).line(line, width, rgb);
  std::vector<float> out;
  for (const S& c : rgb) out.push_back(plain(c));
  return out;
}

}  // namespace raytrace
