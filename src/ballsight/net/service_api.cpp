#include "ballsight/net/service_api.hpp"

namespace ballsight {

ApiContext api_context(CourtService& service, NavigationHub& hub) {
  ApiContext context{hub, service.camera_names(), service.site().court,
                     service.site().ball_radius_m};
  context.on_collected = [&service, &hub] { service.republish(hub); };
  context.camera_view = [&service](std::size_t index) { return service.camera_view(index); };
  context.planner = [&service] { return service.planner(); };
  context.set_planner = [&service, &hub](PlannerKind kind) { service.set_planner(kind, hub); };
  context.drive = service.simulated_drive();
  return context;
}

}  // namespace ballsight
