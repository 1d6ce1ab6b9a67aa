// Adds a 64-bit value to a (lo, hi) pair of buffer or shared words with a software carry: 64-bit atomics
// are optional in Vulkan. Sums are exact and independent of the order threads add in. A macro: GLSL
// atomics take only buffer or shared members, which cannot be passed to functions.
#ifndef RAYLAB_ATOMIC_ADD_64_GLSL
#define RAYLAB_ATOMIC_ADD_64_GLSL

#define ATOMIC_ADD_64(LO_WORD, HI_WORD, VALUE)   \
  {                                              \
    uint64_t v_ = (VALUE);                       \
    uint lo_ = uint(v_);                         \
    uint hi_ = uint(v_ >> 32);                   \
    uint old_ = atomicAdd(LO_WORD, lo_);         \
    if (old_ + lo_ < old_) hi_ += 1u;            \
    if (hi_ != 0u) atomicAdd(HI_WORD, hi_);      \
  }

#endif
