#pragma once
// Core's scene elements, registered by registerCoreElements() in groups.
namespace soak {
class ModuleRegistry;
void registerOutputElements(ModuleRegistry& r);       // Simulation/OutputElements.cpp
void registerClothElement(ModuleRegistry& r);         // Simulation/ClothElement.cpp
void registerWaterSourceElements(ModuleRegistry& r);  // Simulation/WaterSources.cpp
}  // namespace soak
