#include "calc/calc.hpp"

#include <stdexcept>

namespace impetus::cli {

void Registry::add(Model model) {
  if (find(model.name) != nullptr) {
    throw std::logic_error("calc model registered twice: " + model.name);
  }
  models_.push_back(std::move(model));
}

const Model* Registry::find(const std::string& name) const noexcept {
  for (const Model& m : models_) {
    if (m.name == name) {
      return &m;
    }
  }
  return nullptr;
}

const Registry& registry() {
  static const Registry instance = [] {
    Registry r;
    registerMassModels(r);
    registerKinematicsModels(r);
    registerForceModels(r);
    registerKineticsModels(r);
    registerImpactModels(r);
    registerProjectileModels(r);
    registerCannonModels(r);
    registerSensorsModels(r);
    registerDisplayModels(r);
    registerRelativityModels(r);
    registerIntegratorModels(r);
    registerGeoModels(r);
    registerAudioModels(r);
    return r;
  }();
  return instance;
}

} // namespace impetus::cli
