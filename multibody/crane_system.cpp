// Instantiates the crane equations and their shared model for the nodal and the modal elastic
// coordinates.
#include "multibody/crane_system_impl.hpp"

#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace ffrf::multibody {

namespace detail {

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> CraneConstants<Coords>::equations() const {
  return std::make_unique<CraneSystem<Coords>>(this->shared_from_this());
}

template <fem::ElasticCoordinates Coords>
std::shared_ptr<const SharedCraneModel> CraneConstants<Coords>::in_waters(const HullModel& hull,
                                                                         const std::optional<sea::WaveField>& wave) const {
  CraneModel<Coords> crane = model;
  crane.hull = hull;
  crane.wave = wave;
  return std::make_shared<const CraneConstants<Coords>>(std::move(crane));
}

}  // namespace detail

template <fem::ElasticCoordinates Coords>
std::shared_ptr<const SharedCraneModel> make_shared_crane_model(CraneModel<Coords> model) {
  return std::make_shared<const detail::CraneConstants<Coords>>(std::move(model));
}

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<Coords> model) {
  return make_shared_crane_model(std::move(model))->equations();
}

template std::shared_ptr<const SharedCraneModel> make_shared_crane_model(CraneModel<nodal::NodalCoordinates>);
template std::shared_ptr<const SharedCraneModel> make_shared_crane_model(CraneModel<modal::ModalCoordinates>);
template std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<nodal::NodalCoordinates>);
template std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<modal::ModalCoordinates>);

}  // namespace ffrf::multibody
