#pragma once
// What every API error answer must be: the status, and a JSON body naming the error and where.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "ballsight/net/api_routes.hpp"

namespace ballsight::test {

inline void expect_error(const ApiResponse& r, int status, const std::string& where) {
  EXPECT_EQ(r.status, status) << r.body;
  const nlohmann::json j = nlohmann::json::parse(r.body, nullptr, false);
  ASSERT_TRUE(j.is_object()) << r.body;
  EXPECT_TRUE(j.contains("error")) << r.body;
  EXPECT_EQ(j.value("where", ""), where) << r.body;
}

}  // namespace ballsight::test
