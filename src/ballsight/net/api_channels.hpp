#pragma once
// API v1's WebSocket channels (api_routes.hpp): the stream (/api/v1/stream: navigation, world
// and health topics, api.hpp) and Foxglove clients (any path, foxglove.hpp), both fed by the
// hub's publications.

#include "ballsight/net/api.hpp"
#include "ballsight/net/api_routes.hpp"

namespace ballsight {

/// Registers the stream's and Foxglove's channels and the hub's publications with `routes`;
/// `context` must outlive them.
void add_api_v1_channels(ApiRoutes& routes, const ApiContext& context);

}  // namespace ballsight
