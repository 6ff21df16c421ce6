// The wording of a broken connection to the service (sim_client/connection_failure.h):
// the service going away reads the same whether a write or a read noticed it first.
#include <gtest/gtest.h>

#include "sim_client/connection_failure.h"

namespace cloudsvc::test {
namespace {

TEST(ConnectionFailure, TheServiceGoingAwayReadsTheSameFromASendOrAReceive) {
  for (const asio::error_code ec : {asio::error_code(asio::error::broken_pipe), asio::error_code(asio::error::connection_reset),
                                    asio::error_code(asio::error::eof)}) {
    EXPECT_EQ(client::connection_failure_text("send", ec).rfind("connection closed by the service: ", 0), 0u) << ec.message();
    EXPECT_EQ(client::connection_failure_text("receive", ec).rfind("connection closed by the service: ", 0), 0u) << ec.message();
  }
}

TEST(ConnectionFailure, OtherErrorsNameTheOperation) {
  const asio::error_code ec(asio::error::no_buffer_space);
  EXPECT_EQ(client::connection_failure_text("send", ec), "send failed: " + ec.message());
  EXPECT_EQ(client::connection_failure_text("receive", ec), "receive failed: " + ec.message());
}

}  // namespace
}  // namespace cloudsvc::test
