#include "ballsight/net/api_routes.hpp"

#include <gtest/gtest.h>

#include "api_error.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

/// A route whose answer names it (the body "\"<name>\"").
ApiModuleRoute named_route(const std::string& prefix, const std::string& name,
                           bool runs_long = false) {
  return {.prefix = prefix,
          .handler = [name](const ApiRequest&) { return ApiResponse(200, "\"" + name + "\""); },
          .runs_long = runs_long};
}

std::string answered_by(const ApiRoutes& routes, const std::string& target) {
  return routes.answer({"GET", target, "", false}).body;
}

TEST(ApiRoutes, TheLongestPrefixOfWholeSegmentsAnswers) {
  ApiRoutes routes;
  // Registered in any order: the longest prefix wins, not the first.
  routes.add(named_route("/api/v1/omni/", "omni", true));
  routes.add(named_route("/api/v1/", "v1"));
  routes.add(named_route("/api/v1/omni/fits/", "fits"));
  EXPECT_EQ(answered_by(routes, "/api/v1/omni/frames"), "\"omni\"");
  EXPECT_EQ(answered_by(routes, "/api/v1/omni/fits/3?format=iris"), "\"fits\"");
  EXPECT_EQ(answered_by(routes, "/api/v1/navigation?after=/api/v1/omni/"), "\"v1\"");
  // A prefix matches whole segments: /api/v1/omnibus is not the omni API's.
  EXPECT_EQ(answered_by(routes, "/api/v1/omnibus"), "\"v1\"");
  EXPECT_EQ(answered_by(routes, "/api/v1/omni"), "\"v1\"");
}

TEST(ApiRoutes, NoRouteIsA404NamingThePath) {
  ApiRoutes routes;
  test::expect_error(routes.answer({"GET", "/api/v1/robot", "", true}), 404, "/api/v1/robot");
  routes.add(named_route("/api/v1/", "v1"));
  test::expect_error(routes.answer({"PUT", "/nothing?x=1", "{}", true}), 404, "/nothing");
  test::expect_error(routes.answer({"GET", "/api/v1", "", true}), 404, "/api/v1");
}

TEST(ApiRoutes, RunsLongIsTheMatchingRoutes) {
  ApiRoutes routes;
  routes.add(named_route("/api/v1/", "v1"));
  routes.add(named_route("/api/v1/cameras/", "cameras", true));
  EXPECT_TRUE(routes.runs_long("/api/v1/cameras/ne/view"));
  EXPECT_TRUE(routes.runs_long("/api/v1/cameras/ne/view?width=640"));
  EXPECT_FALSE(routes.runs_long("/api/v1/navigation?after=3"));
  EXPECT_FALSE(routes.runs_long("/api/v1/camera/ne/view"));
  EXPECT_FALSE(routes.runs_long("/elsewhere/cameras/"));
}

TEST(ApiRoutes, ADuplicateOrMalformedRouteIsRefused) {
  ApiRoutes routes;
  routes.add(named_route("/api/v1/", "v1"));
  try {
    routes.add(named_route("/api/v1/", "again"));
    ADD_FAILURE() << "a second route on /api/v1/ was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "API route '/api/v1/': registered twice");
  }
  EXPECT_THROW(routes.add(named_route("/api/v1/omni", "no end")), InputError);
  EXPECT_THROW(routes.add(named_route("api/v1/omni/", "no start")), InputError);
  EXPECT_THROW(routes.add(named_route("", "empty")), InputError);
  EXPECT_THROW(routes.add({.prefix = "/api/v2/", .handler = {}}), InputError);
  // The refused routes changed nothing.
  EXPECT_EQ(answered_by(routes, "/api/v1/omni/x"), "\"v1\"");
  test::expect_error(routes.answer({"GET", "/api/v2/x", "", true}), 404, "/api/v2/x");
}

}  // namespace
}  // namespace ballsight
