// One wording for a broken connection to the service, used by every client connection
// (ServiceConnection, the soak clients). When the service closes its end, whether the
// client's next write (broken pipe, reset) or its pending read (end of file, reset)
// notices first is a race; either way the user is told the same thing.
#pragma once

#include <asio/error.hpp>
#include <asio/error_code.hpp>

#include <string>

namespace cloudsvc::client {

// True for the errors that mean the peer closed or reset the connection.
inline bool closed_by_peer(const asio::error_code& ec) {
  return ec == asio::error::eof || ec == asio::error::broken_pipe || ec == asio::error::connection_reset ||
         ec == asio::error::connection_aborted;
}

// "connection closed by the service: <system message>" when the service went away,
// otherwise "<operation> failed: <system message>" (operation: "send" or "receive").
inline std::string connection_failure_text(const char* operation, const asio::error_code& ec) {
  if (closed_by_peer(ec)) return "connection closed by the service: " + ec.message();
  return std::string(operation) + " failed: " + ec.message();
}

}  // namespace cloudsvc::client
