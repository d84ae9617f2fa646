#pragma once
// Whole-array operations with one implementation per device.
#include <cstdint>

#include "Backend/Device.h"

namespace soak {

// Sum in double precision. On the CPU the summation order is fixed (chunks of
// 4096 added in order), so the result does not depend on the thread count.
double reduceSum(Device d, const float* x, int n);
float reduceMax(Device d, const float* x, int n);  // -3e38 for n == 0
// The same into *out (device memory), without waiting for the device.
void reduceMaxInto(Device d, const float* x, int n, float* out);
float reduceMin(Device d, const float* x, int n);  // +3e38 for n == 0
// out[i] = sum of in[0..i); returns the total.
int exclusiveScan(Device d, const int* in, int* out, int n);
// The same without returning the total: on the GPU nothing waits for the
// device (exclusiveScan reads the total back, a host-device synchronisation).
void exclusiveScanAsync(Device d, const int* in, int* out, int n);
// Stable sort of pairs by the low keyBits bits of the key.
void sortPairs(Device d, std::uint32_t* keys, std::uint32_t* values, int n, int keyBits);

}  // namespace soak
