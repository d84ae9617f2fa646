#pragma once
// DLPack's C structures (dlpack.h, v0.8: the unversioned DLManagedTensor
// that a "dltensor" capsule holds), written out so that the module needs no
// external header. The layout is the ABI every consumer (PyTorch, CuPy,
// JAX, numpy.from_dlpack) reads; the field order and types must not change.
#include <cstdint>

namespace soak::dlpack {

enum DeviceType : std::int32_t { kDLCPU = 1, kDLCUDA = 2 };
enum TypeCode : std::uint8_t { kDLInt = 0, kDLUInt = 1, kDLFloat = 2 };

struct DLDevice {
  std::int32_t device_type;  // DeviceType (a C enum: 4 bytes)
  std::int32_t device_id;
};

struct DLDataType {
  std::uint8_t code;  // TypeCode
  std::uint8_t bits;
  std::uint16_t lanes;
};

struct DLTensor {
  void* data;
  DLDevice device;
  std::int32_t ndim;
  DLDataType dtype;
  std::int64_t* shape;
  std::int64_t* strides;  // in elements; null means compact row-major
  std::uint64_t byte_offset;
};

struct DLManagedTensor {
  DLTensor dl_tensor;
  void* manager_ctx;
  void (*deleter)(DLManagedTensor* self);
};

static_assert(sizeof(DLDevice) == 8 && sizeof(DLDataType) == 4, "DLPack layout");
static_assert(sizeof(DLTensor) == 48 && sizeof(DLManagedTensor) == 64, "DLPack layout (64-bit)");

}  // namespace soak::dlpack
