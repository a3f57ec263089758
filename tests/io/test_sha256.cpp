#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "runtime/io/sha256.h"

namespace fs = std::filesystem;
using ksmc::runtime::io::sha256_hex;

TEST_CASE("sha256: FIPS 180-4 test vectors") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex(std::string(1000000, 'a')) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("sha256: pieces of any size give the whole's digest; files too") {
  const std::string text(1000, 'x');
  for (const std::size_t step : {1UL, 7UL, 55UL, 56UL, 63UL, 64UL, 65UL, 999UL}) {
    ksmc::runtime::io::Sha256 h;
    for (std::size_t i = 0; i < text.size(); i += step) h.update(std::string_view(text).substr(i, step));
    INFO(step);
    CHECK(h.hex() == sha256_hex(text));
  }
  const fs::path p = fs::temp_directory_path() / "ksmc_sha256_test.bin";
  std::ofstream(p, std::ios::binary) << text;
  const auto d = ksmc::runtime::io::sha256_file(p);
  CHECK(d.bytes == 1000);
  CHECK(d.sha256 == sha256_hex(text));
  fs::remove(p);
  CHECK_THROWS_WITH(ksmc::runtime::io::sha256_file(p), Catch::Contains("ksmc_sha256_test.bin: cannot open"));
}
