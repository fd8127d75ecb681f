// openswarm.json's "parameters" (cli/src/app_parameters.cpp): what is
// valid, what is refused with the place and the fix, and how values given
// for a build are checked, told apart and written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "../../cli/src/app_config.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace openswarm;

namespace {

// An app folder holding openswarm.json with these "parameters".
class AppParameters : public ::testing::Test {
  protected:
    fs::path dir = fs::temp_directory_path() / ("app_parameters_" + std::to_string(getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }

    AppConfig load(const std::string &parameters) {
        std::ofstream(dir / "openswarm.json")
            << R"({"name": "app", "port": "kilobot", "parameters": )" << parameters << "}\n";
        return load_app_config(dir);
    }
    // The message load gives (empty if it loads).
    std::string refusal(const std::string &parameters) {
        try {
            load(parameters);
        } catch (const ConfigError &e) {
            return e.what();
        }
        return "";
    }
};

}  // namespace

TEST_F(AppParameters, LoadsDefaultRangeAndDoc) {
    AppConfig c = load(R"({"SPEED": {"default": 50, "min": 0, "max": 255, "doc": "motor duty"}, "GAP_MM": {"default": -3}})");
    ASSERT_EQ(c.parameters.size(), 2u);
    EXPECT_EQ(c.parameters[0].name, "GAP_MM"); // by name
    EXPECT_EQ(c.parameters[0].value, -3);
    EXPECT_EQ(c.parameters[0].min, -2147483647L - 1); // a 32-bit long, without a range
    EXPECT_EQ(c.parameters[1].name, "SPEED");
    EXPECT_EQ(c.parameters[1].max, 255);
    EXPECT_EQ(c.parameters[1].doc, "motor duty");
}

TEST_F(AppParameters, RefusesWithThePlaceAndTheFix) {
    EXPECT_NE(refusal(R"({"SPEED": {"default": 300, "min": 0, "max": 255}})")
                  .find("\"parameters.SPEED.default\": expected a whole number 0..255, found number 300"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"SPEED": {"default": 0.5}})").find("\"parameters.SPEED.default\": expected a whole number"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"SPEED": {"min": 0}})").find("\"parameters.SPEED.default\": missing; add \"default\" there"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"speed": {"default": 1}})").find("\"parameters.speed\": \"speed\" cannot name a parameter: "
                                                         "upper-case letters"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"EV_GO": {"default": 1}})").find("the build's own macros start with EV_"), std::string::npos);
    EXPECT_NE(refusal(R"({"OS_X": {"default": 1}})").find("the SDK's names start with OS_"), std::string::npos);
    EXPECT_NE(refusal(R"({"SPEED": {"default": 1, "min": 5, "max": 2}})")
                  .find("\"parameters.SPEED.max\": the range is empty: \"max\" 2 is below \"min\" 5; swap them"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"SPEED": {"default": 1, "dflt": 2}})").find("did you mean \"default\""), std::string::npos);
    EXPECT_NE(refusal(R"([1])").find("\"parameters\": expected an object"), std::string::npos);
    EXPECT_NE(refusal(R"({"SPEED": {"default": 1, "doc": "a */ b"}})").find("\"parameters.SPEED.doc\""),
              std::string::npos);
}

TEST_F(AppParameters, ChecksValuesGivenForABuild) {
    AppConfig c = load(R"({"SPEED": {"default": 50, "min": 0, "max": 255}})");
    EXPECT_EQ(parameter_problem(c, "SPEED", 80), "");
    EXPECT_NE(parameter_problem(c, "SPEED", 256).find("parameter SPEED takes a whole number 0..255"), std::string::npos);
    EXPECT_NE(parameter_problem(c, "SPEED", "fast").find("found string"), std::string::npos);
    std::string unknown = parameter_problem(c, "SPEEED", 1);
    EXPECT_NE(unknown.find("declares no parameter \"SPEEED\" (it declares SPEED) (did you mean \"SPEED\"?)"),
              std::string::npos)
        << unknown;
    EXPECT_NE(unknown.find("declare it under \"parameters\" there"), std::string::npos);
}

TEST_F(AppParameters, ParsesSettingsFromTheCommandLine) {
    ParameterValues values;
    std::string why;
    EXPECT_TRUE(parse_parameter_setting("SPEED=80", values, why));
    EXPECT_TRUE(parse_parameter_setting("GAP=-4", values, why));
    EXPECT_EQ(values, (ParameterValues{{"GAP", -4}, {"SPEED", 80}}));
    for (const char *bad : {"SPEED", "SPEED=", "=3", "SPEED=8x", "SPEED= 8", "SPEED=99999999999999999999"}) {
        EXPECT_FALSE(parse_parameter_setting(bad, values, why)) << bad;
        EXPECT_NE(why.find("expected NAME=VALUE"), std::string::npos) << why;
    }
    EXPECT_FALSE(parse_parameter_setting("SPEED=81", values, why));
    EXPECT_EQ(why, "-D SPEED is given twice: keep one");
}

TEST_F(AppParameters, OnlyValuesOtherThanTheDefaultsMakeAnotherBuild) {
    AppConfig c = load(R"({"SPEED": {"default": 50}, "TURN": {"default": 3}})");
    EXPECT_TRUE(changed_parameters(c, {{"SPEED", 50}}).empty());
    EXPECT_EQ(parameters_folder_suffix({}), "");
    ParameterValues a = changed_parameters(c, {{"SPEED", 80}, {"TURN", 3}});
    EXPECT_EQ(a, (ParameterValues{{"SPEED", 80}}));
    EXPECT_EQ(parameters_cmake_list({{"SPEED", 80}, {"TURN", -1}}), "SPEED=80;TURN=-1");
    std::string suffix = parameters_folder_suffix(a);
    EXPECT_EQ(suffix.size(), 18u); // "-p" and 16 hex digits
    EXPECT_NE(suffix, parameters_folder_suffix({{"SPEED", 81}}));
    EXPECT_EQ(suffix, parameters_folder_suffix({{"SPEED", 80}}));
}

TEST_F(AppParameters, TheHeaderDefinesEachDefaultUnlessTheBuildDid) {
    AppConfig c = load(R"({"SPEED": {"default": 50, "min": 0, "max": 255, "doc": "motor duty"}, "GAP": {"default": -3}})");
    std::string h = parameters_header(c);
    EXPECT_NE(h.find("/* motor duty (0..255) */\n#ifndef SPEED\n#define SPEED 50\n#endif\n"), std::string::npos) << h;
    EXPECT_NE(h.find("#ifndef GAP\n#define GAP (-3)\n#endif\n"), std::string::npos) << h;
}

TEST_F(AppParameters, EepromValuesGetAddressesAndAReaderFallingBackToTheDefault) {
    AppConfig c = load(R"({"TURN": {"default": 3, "min": -5, "max": 5, "at": "eeprom"},
                           "SPEED": {"default": 50, "min": 0, "max": 255, "at": "build"},
                           "HALF": {"default": 250, "min": 10, "max": 5000, "at": "eeprom"}})");
    // In the order of their names, from 0x100: kilolib's bytes lie below.
    EXPECT_TRUE(find_parameter(c, "HALF")->in_eeprom);
    EXPECT_EQ(find_parameter(c, "HALF")->eeprom_address, 0x100u);
    EXPECT_FALSE(find_parameter(c, "SPEED")->in_eeprom);
    EXPECT_EQ(find_parameter(c, "TURN")->eeprom_address, 0x104u);
    // value - min, little-endian: an erased EEPROM reads above max - min.
    EXPECT_EQ(eeprom_parameter_bytes_of(*find_parameter(c, "HALF"), 500), (std::vector<unsigned>{234, 1, 0, 0}));
    EXPECT_EQ(eeprom_parameter_bytes_of(*find_parameter(c, "TURN"), -5), (std::vector<unsigned>{0, 0, 0, 0}));
    std::string h = parameters_header(c);
    EXPECT_NE(h.find("#include <avr/eeprom.h>"), std::string::npos) << h;
    EXPECT_NE(h.find("#define TURN_EEPROM_ADDRESS 0x104\n#ifndef TURN\n#define TURN openswarm_eeprom_parameter("
                     "TURN_EEPROM_ADDRESS, (-5L), 10UL, 3L)\n#endif\n"),
              std::string::npos)
        << h;
    EXPECT_NE(h.find("#ifndef SPEED\n#define SPEED 50\n#endif\n"), std::string::npos) << h;
}

TEST_F(AppParameters, EepromValuesRefusedWithTheFix) {
    EXPECT_NE(refusal(R"({"HALF": {"default": 250, "at": "eeprom"}})").find(
                  "\"parameters.HALF.at\": a value read from the EEPROM needs a range narrower"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"HALF": {"default": 250, "min": 0, "max": 900, "at": "epprom"}})")
                  .find("unknown choice \"epprom\"; expected \"build\""),
              std::string::npos);
    std::ofstream(dir / "openswarm.json")
        << R"({"name": "app", "port": "epuck_world", "parameters": {"HALF": {"default": 1, "min": 0, "max": 9, "at": "eeprom"}}})";
    try {
        load_app_config(dir);
        ADD_FAILURE() << "an e-puck app's EEPROM value loaded";
    } catch (const ConfigError &e) {
        EXPECT_NE(std::string(e.what()).find("only a Kilobot's values are read from its EEPROM"), std::string::npos)
            << e.what();
    }
}
