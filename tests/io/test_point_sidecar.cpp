#include "dfvn/io/point_sidecar.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace dfvn {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path = fs::temp_directory_path() / ("dfvn-sidecar-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                               "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Folder() { fs::create_directories(path); }
  ~Folder() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(PointSidecar, RoundTripsEveryDomain) {
  const Folder folder;
  const std::string points = folder.file("set.npy");
  EXPECT_EQ(point_sidecar_path(points), points + ".json");
  EXPECT_EQ(point_sidecar_path("-"), "");
  EXPECT_FALSE(read_point_sidecar_domain(points).has_value());  // none written yet
  for (const Domain& d : {Domain::unit(DomainKind::torus), Domain(DomainKind::cube, -0.04, 1.08),
                          Domain::unit(DomainKind::ball), Domain::unit(DomainKind::sphere),
                          Domain(DomainKind::cube, 0.0, 0.1 + 0.2)}) {
    write(point_sidecar_path(points), point_sidecar_json(d, 7, {279936}, R"({"method": "cnj", "seeds": [1]})"));
    const auto read = read_point_sidecar_domain(points, 7);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(*read, d);  // the same doubles: JSON keeps 17 digits
  }
}

TEST(PointSidecar, RefusesWhatIsNotOne) {
  const Folder folder;
  const std::string points = folder.file("set.dat");
  const std::string sidecar = point_sidecar_path(points);
  for (const std::string& text :
       {std::string("not json"), std::string("[1, 2]"), std::string(R"({"format": "something else", "version": 1})"),
        std::string(R"({"format": "dfvn-sample point set", "version": 2, "domain": {"kind": "torus", "lo": 0, "side": 1}})"),
        std::string(R"({"format": "dfvn-sample point set", "version": 1})"),
        std::string(R"({"format": "dfvn-sample point set", "version": 1, "domain": {"kind": "box", "lo": 0, "side": 1}})"),
        std::string(R"({"format": "dfvn-sample point set", "version": 1, "domain": {"kind": "cube", "lo": 0, "side": -1}})"),
        std::string(R"({"format": "dfvn-sample point set", "version": 1, "dimension": 3, "domain": {"kind": "cube", "lo": 0, "side": 1}})")}) {
    write(sidecar, text);
    EXPECT_THROW(read_point_sidecar_domain(points, 7), std::invalid_argument) << text;
  }
  fs::remove(sidecar);
  fs::create_directory(sidecar);  // a folder where the file would be
  EXPECT_THROW(read_point_sidecar_domain(points), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
