// Instantiates the crane equations for the nodal and the modal elastic coordinates.
#include "coupling/crane_system_impl.hpp"

#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace ffrf::coupling {

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<Coords> model) {
  return std::make_unique<detail::CraneSystem<Coords>>(std::move(model));
}

template std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<nodal::NodalCoordinates>);
template std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<modal::ModalCoordinates>);

}  // namespace ffrf::coupling
