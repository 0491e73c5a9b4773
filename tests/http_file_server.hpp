#pragma once
// A tiny HTTP/1.0 server for tests of URL sources: it serves one file at every path on 127.0.0.1
// (a free port), one connection at a time, without byte ranges (a stream, as an IP camera's), and
// stops when destroyed. Also a port on 127.0.0.1 where nothing listens.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>

namespace ballsight::test {

namespace detail {

// A listening TCP socket on 127.0.0.1 at a port the system chose.
inline int listen_on_loopback(int& port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) throw std::runtime_error("socket() failed");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof address;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(fd, 4) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    ::close(fd);
    throw std::runtime_error("cannot listen on 127.0.0.1");
  }
  port = ntohs(address.sin_port);
  return fd;
}

}  // namespace detail

/// A port on 127.0.0.1 that was free a moment ago (connections to it are refused).
inline int closed_loopback_port() {
  int port = 0;
  ::close(detail::listen_on_loopback(port));
  return port;
}

class HttpFileServer {
 public:
  explicit HttpFileServer(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    body_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (body_.empty()) throw std::runtime_error("nothing to serve in " + file.string());
    listen_fd_ = detail::listen_on_loopback(port_);
    thread_ = std::thread([this] { serve(); });
  }
  ~HttpFileServer() {
    stop_ = true;
    thread_.join();
    ::close(listen_fd_);
  }
  HttpFileServer(const HttpFileServer&) = delete;
  HttpFileServer& operator=(const HttpFileServer&) = delete;

  std::string url(const std::string& name) const {
    return "http://127.0.0.1:" + std::to_string(port_) + "/" + name;
  }
  int requests() const { return requests_; }

 private:
  void serve() {
    while (!stop_) {
      pollfd listening{listen_fd_, POLLIN, 0};
      if (::poll(&listening, 1, 20) <= 0) continue;
      const int client = ::accept(listen_fd_, nullptr, nullptr);
      if (client < 0) continue;
      ++requests_;
      answer(client);
      ::close(client);
    }
  }

  // Reads the request head (up to a blank line, at most 2 s) and sends the whole file.
  void answer(int client) const {
    const timeval timeout{2, 0};
    ::setsockopt(client, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    ::setsockopt(client, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
    std::string head;
    char buffer[1024];
    while (head.find("\r\n\r\n") == std::string::npos && head.size() < 65536) {
      const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
      if (n <= 0) return;
      head.append(buffer, static_cast<size_t>(n));
    }
    const std::string reply =
        "HTTP/1.0 200 OK\r\nContent-Type: application/octet-stream\r\n"
        "Content-Length: " +
        std::to_string(body_.size()) + "\r\nConnection: close\r\n\r\n" + body_;
    for (size_t sent = 0; sent < reply.size() && !stop_;) {
      const ssize_t n = ::send(client, reply.data() + sent, reply.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return;  // the client hung up (it read what it wanted) or stalled
      sent += static_cast<size_t>(n);
    }
  }

  std::string body_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> requests_{0};
  std::thread thread_;
};

}  // namespace ballsight::test
