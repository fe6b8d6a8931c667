// Instantiates the crane equations and their shared model for the nodal and the modal elastic
// coordinates, each with the hull's fixed 3 × 3 rigid block and with an articulated one (a pinned heel,
// bodies pinned to the hull).
#include "multibody/crane_equations_of.hpp"

#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace ffrf::multibody {

namespace detail {

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> CraneModelOf<Coords>::equations() const {
  if (layout.articulated()) return std::make_unique<CraneEquationsOf<Coords, true>>(this->shared_from_this());
  return std::make_unique<CraneEquationsOf<Coords, false>>(this->shared_from_this());
}

template <fem::ElasticCoordinates Coords>
std::shared_ptr<const CraneModel> CraneModelOf<Coords>::in_waters(const HullModel& hull,
                                                                         const std::optional<sea::WaveField>& wave) const {
  CraneParameters<Coords> crane = model;
  crane.hull = hull;
  crane.wave = wave;
  return std::make_shared<const CraneModelOf<Coords>>(std::move(crane));
}

}  // namespace detail

template <fem::ElasticCoordinates Coords>
std::shared_ptr<const CraneModel> make_crane_model(CraneParameters<Coords> model) {
  return std::make_shared<const detail::CraneModelOf<Coords>>(std::move(model));
}

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneParameters<Coords> model) {
  return make_crane_model(std::move(model))->equations();
}

template std::shared_ptr<const CraneModel> make_crane_model(CraneParameters<nodal::NodalCoordinates>);
template std::shared_ptr<const CraneModel> make_crane_model(CraneParameters<modal::ModalCoordinates>);
template std::unique_ptr<CraneEquations> make_crane_equations(CraneParameters<nodal::NodalCoordinates>);
template std::unique_ptr<CraneEquations> make_crane_equations(CraneParameters<modal::ModalCoordinates>);

}  // namespace ffrf::multibody
