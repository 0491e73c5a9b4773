#pragma once
// One HTTP/1.1 request to a service on 127.0.0.1 and its JSON reply, for the tests of `serve` and
// `court-node --serve`.

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace ballsight::test {

struct Reply {
  int status = 0;
  nlohmann::json body;
};

inline Reply request(unsigned short port, boost::beast::http::verb verb, const std::string& target,
                     const std::string& body = "", const std::string& token = "") {
  namespace asio = boost::asio;
  namespace http = boost::beast::http;
  asio::io_context io;
  asio::ip::tcp::socket socket(io);
  socket.connect({asio::ip::make_address("127.0.0.1"), port});
  http::request<http::string_body> req{verb, target, 11};
  req.set(http::field::host, "127.0.0.1");
  if (!token.empty()) req.set(http::field::authorization, "Bearer " + token);
  req.body() = body;
  req.prepare_payload();
  http::write(socket, req);
  boost::beast::flat_buffer buffer;
  http::response<http::string_body> res;
  http::read(socket, buffer, res);
  return {static_cast<int>(res.result_int()),
          res.body().empty() ? nlohmann::json() : nlohmann::json::parse(res.body())};
}

}  // namespace ballsight::test
