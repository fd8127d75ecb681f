// world.json's "fidelity" (docs/world.md): "exact" by default, "native",
// and "qemu" - an e-puck world's controllers are e-puck2 images run by
// QEMU - which a world of Kilobots may not ask for: refused at its place,
// with the fix.
#include <gtest/gtest.h>

#include <string>

#include "world_file_fixture.hpp"

namespace {

const std::string arena = R"("arena": {"width_mm": 600, "height_mm": 400})";

class WorldFidelity : public WorldFile {
  protected:
    int fidelity_of(const std::string &text) {
        world_spec w{};
        std::string err = load(text, &w);
        EXPECT_EQ(err, "");
        int fidelity = w.fidelity;
        if (err.empty()) world_spec_free(&w);
        return fidelity;
    }
};

TEST_F(WorldFidelity, Values) {
    EXPECT_EQ(fidelity_of("{" + arena + "}"), WORLD_FIDELITY_EXACT);
    EXPECT_EQ(fidelity_of("{" + arena + R"(, "fidelity": "native"})"), WORLD_FIDELITY_NATIVE);
    EXPECT_EQ(fidelity_of("{" + arena + R"(, "robot": "epuck", "fidelity": "qemu"})"), WORLD_FIDELITY_QEMU);
    EXPECT_EQ(fidelity_of("{" + arena + R"(, "robot": "epuck", "fidelity": "exact"})"), WORLD_FIDELITY_EXACT);
}

TEST_F(WorldFidelity, QemuIsRefusedForKilobots) {
    std::string err = error_of("{" + arena + R"(, "fidelity": "qemu"})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:1:60: fidelity: \"qemu\" runs e-puck2 images, and this is a world of Kilobots: give "
              "\"robot\": \"epuck\" with images built by `openswarm build --qemu`, or \"exact\" or \"native\" for "
              "Kilobots");
    err = error_of("{" + arena + R"(, "fidelity": "qemo"})");
    EXPECT_NE(err.find("known: exact (the firmware in simavr, an e-puck's host program), native (the app built for "
                       "the host), qemu (an e-puck's e-puck2 image under QEMU) (did you mean \"qemu\"?)"),
              std::string::npos)
        << err;
}

}  // namespace
