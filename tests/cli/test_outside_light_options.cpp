// --sky and --sun: what each form of the value gives, and one line naming the option for each bad value.
#include <gtest/gtest.h>

#include <cmath>

#include "expect_input_error.hpp"
#include "pipeline/outside_light_options.hpp"

namespace rad {
namespace {

TEST(OutsideLightOptions, SkyForms) {
    const Sky grey = parse_sky("2");
    EXPECT_EQ(grey.kind, Sky::Kind::uniform);
    EXPECT_EQ(grey.radiance, glm::dvec3(2.0));
    const Sky blue = parse_sky("overcast,0.5,0.75,1");
    EXPECT_EQ(blue.kind, Sky::Kind::overcast);
    EXPECT_EQ(blue.radiance, glm::dvec3(0.5, 0.75, 1.0));
    EXPECT_FALSE(parse_sky("none").present());
}

TEST(OutsideLightOptions, SunForms) {
    const Sun sun = parse_sun("0,2,0,3");
    EXPECT_EQ(sun.direction, glm::dvec3(0, 1, 0));  // normalized
    EXPECT_EQ(sun.irradiance, glm::dvec3(3.0));
    const Sun coloured = parse_sun("1,1,0,1,2,3");
    EXPECT_NEAR(coloured.direction.x, std::sqrt(0.5), 1e-15);
    EXPECT_EQ(coloured.irradiance, glm::dvec3(1, 2, 3));
    EXPECT_FALSE(parse_sun("none").present());
}

TEST(OutsideLightOptions, BadValuesAreRefusedNamingTheOption) {
    test::expect_input_error(parse_sky, "1,2", {"--sky: 2 numbers; want R,G,B"});
    test::expect_input_error(parse_sky, "overcast,-1", {"--sky: the radiance '-1' is negative"});
    test::expect_input_error(parse_sky, "foggy,1", {"--sky: 'foggy' is not a number"});
    test::expect_input_error(parse_sky, "1,inf,1", {"--sky: 'inf' is not a number"});
    test::expect_input_error(parse_sun, "0,0,0,3", {"--sun: the direction X,Y,Z is zero"});
    test::expect_input_error(parse_sun, "0,1,0,-2", {"--sun: the irradiance '-2' is negative"});
    test::expect_input_error(parse_sun, "1,1,1,nan", {"--sun: 'nan' is not a number"});
    test::expect_input_error(parse_sun, "1,1,1", {"--sun: 3 numbers; want X,Y,Z,E"});
}

}  // namespace
}  // namespace rad
