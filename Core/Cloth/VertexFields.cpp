#include "Cloth/VertexFields.h"

#include <vector>

namespace soak {

float* VertexFields::get(const std::string& name, int vertexCount, float initial) {
  auto it = fields_.find(name);
  if (it == fields_.end()) {
    auto buffer = std::make_unique<Buffer<float>>(device_);
    buffer->upload(std::vector<float>(std::size_t(vertexCount), initial));
    it = fields_.emplace(name, std::move(buffer)).first;
  }
  return it->second->data();
}

const float* VertexFields::find(const std::string& name) const {
  const auto it = fields_.find(name);
  return it == fields_.end() ? nullptr : it->second->data();
}

}  // namespace soak
