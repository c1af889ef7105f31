// The response classes as the gathers see them (core/physics/temporal_response.md,
// physics::ResponseClassTable): a program compiled with RESPONSE_CLASSES (a
// render whose table has delayed classes: GatherResponseClasses.h) reads the
// table's `compose` from a buffer and sends a contribution of class c >= 1
// to its class's difference buffer (footprint_deposit.glsl's
// depositDelayed); class 0 takes the deposit of a render without delays.
// RESPONSE_KERNEL_COUNT is the table's base kernels K.
#ifndef TOFSIM_RESPONSE_CLASSES_GLSL
#define TOFSIM_RESPONSE_CLASSES_GLSL

// compose[c * (K + 1) + k]: the class of a path of class c that then meets a
// vertex of base kernel k (ScatterVertex::response).
layout(std430, binding = TOFSIM_SSBO_RESPONSE_COMPOSE) readonly buffer ResponseCompose {
  uint responseCompose[];
};

// ResponseClassTable::kNoClass: a path deeper than the table. The driver
// builds the table for bounces + 1 delayed vertices, so no gather meets it;
// should one, its light is taken as instant rather than written out of the
// buffer.
const uint RESPONSE_NO_CLASS = 0xffffffffu;

// ResponseClassTable::then: class c followed by a vertex of base kernel k.
uint responseClassThen(uint c, int k) {
  uint next = responseCompose[c * uint(RESPONSE_KERNEL_COUNT + 1) + uint(k)];
  return next == RESPONSE_NO_CLASS ? 0u : next;
}

// ResponseClassTable::single: a vertex of base kernel k lit directly.
uint responseClassSingle(int k) { return responseClassThen(0u, k); }

#endif  // TOFSIM_RESPONSE_CLASSES_GLSL
