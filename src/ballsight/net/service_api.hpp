#pragma once
// API v1 over a court service: the adapter between the transport-free service
// (service/court_service.hpp) and the API's handlers (api.hpp).

#include "ballsight/net/api.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight {

/// API v1's view of `service` over `hub` (both must outlive it): its cameras and court, their
/// last frames, the planner's choice, balls reported collected re-planned at once, and the
/// simulated court's robot drive where the service has one.
ApiContext api_context(CourtService& service, NavigationHub& hub);

}  // namespace ballsight
