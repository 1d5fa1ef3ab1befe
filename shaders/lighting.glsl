// lighting.glsl: what the lit shading models share, included by their .vert and .frag files.
// The uniform block (std140, set 0, binding 0: too big for push constants), the object-space
// transforms, and the two light models, each a function of the surface point, its normal and
// its colour in the space the light is given in. C++ twin: lighting.hpp; keep them reading alike.
// `precise` keeps every product and sum rounded on its own, in the written order.

layout(std140, set = 0, binding = 0) uniform Lighting {
  mat4 modelViewProjection;  // object -> clip
  mat4 modelToLighting;      // object -> the space light is computed in (world, or camera for Phong)
  mat4 normalToLighting;     // object normals -> that space (inverse transpose; columns' xyz used)
  vec4 lightPosition;        // in that space; w unused
  vec4 lightPower;           // the course's P (RGB), or Phong's light colour
  vec4 indirect;             // the course's constant indirect light N, or Phong's ambient light
  vec4 specular;             // Phong: specular reflectance (rgb) and shininess (w)
  float pointSize;
  mat4 modelToShadow;        // object -> the clip space of the pass whose depth is the shadow map
  vec4 shadow;               // x: the depth bias subtracted from the shadow map's reference
} u;

vec4 toClip(vec3 p) {
  precise vec4 clip = u.modelViewProjection[0] * p.x + u.modelViewProjection[1] * p.y +
                      u.modelViewProjection[2] * p.z + u.modelViewProjection[3];
  return clip;
}

vec4 toShadow(vec3 p) {
  precise vec4 s = u.modelToShadow[0] * p.x + u.modelToShadow[1] * p.y + u.modelToShadow[2] * p.z + u.modelToShadow[3];
  return s;
}

vec3 toLighting(vec3 p) {
  precise vec3 q = u.modelToLighting[0].xyz * p.x + u.modelToLighting[1].xyz * p.y +
                   u.modelToLighting[2].xyz * p.z + u.modelToLighting[3].xyz;
  return q;
}

vec3 directionToLighting(vec3 d) {
  precise vec3 m = u.modelToLighting[0].xyz * d.x + u.modelToLighting[1].xyz * d.y + u.modelToLighting[2].xyz * d.z;
  return m;
}

vec3 normalToLighting(vec3 n) {
  precise vec3 m = u.normalToLighting[0].xyz * n.x + u.normalToLighting[1].xyz * n.y +
                   u.normalToLighting[2].xyz * n.z;
  return m;
}

// The course's omni light: R = rho * (D + N), D = P * max(r^.n^, 0) / (4 pi |r|^2), r from the
// surface point to the light.
vec3 courseLight(vec3 position, vec3 normal, vec3 rho) {
  precise vec3 n = normalize(normal);
  precise vec3 r = u.lightPosition.xyz - position;
  precise float r2 = dot(r, r);
  precise float cosine = max(dot(normalize(r), n), 0.0);
  precise vec3 direct = u.lightPower.rgb * cosine / (12.566370614359172 * r2);
  precise vec3 reflected = rho * (direct + u.indirect.rgb);
  return reflected;
}

// Phong (BLINN 0) or Blinn-Phong (BLINN 1) in camera space (the eye at the origin): ambient +
// (diffuse + specular) * visibility, kd the surface colour, visibility the fraction of the light
// that reaches the point (1 without shadows: x * 1 is x, so unshadowed models lose nothing).
vec3 phongLightVisible(vec3 position, vec3 normal, vec3 kd, float visibility) {
  precise vec3 n = normalize(normal);
  precise vec3 l = normalize(u.lightPosition.xyz - position);
  precise vec3 v = normalize(-position);
  precise float diffuse = max(dot(n, l), 0.0);
#if BLINN
  precise float facing = max(dot(n, normalize(l + v)), 0.0);
#else
  precise float facing = max(dot(reflect(-l, n), v), 0.0);
#endif
  precise float highlight = pow(facing, u.specular.w);
  precise vec3 colour = (u.indirect.rgb * kd + ((kd * diffuse) * u.lightPower.rgb) * visibility) +
                        ((u.specular.rgb * highlight) * u.lightPower.rgb) * visibility;
  return colour;
}

vec3 phongLight(vec3 position, vec3 normal, vec3 kd) { return phongLightVisible(position, normal, kd, 1.0); }
