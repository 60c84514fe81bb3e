#include "io/json_fields.h"

#include <gtest/gtest.h>

#include <limits>

#include "sim/input_error.h"

namespace {

using nlohmann::json;

TEST(WholeNumber, AnySpellingOfAWholeNumberWithinRange) {
  for (const char* text : {"10", "10.0", "1e1", "1E1", "100e-1", "0.1e2", "1.0e+1"}) {
    EXPECT_EQ(wobble::whole_number(json::parse(text), 1, 50), 10) << text;
  }
  EXPECT_EQ(wobble::whole_number(json::parse("-3.0"), -5, 5), -3);
  EXPECT_EQ(wobble::whole_number(json::parse("-0.0"), -5, 5), 0);
  EXPECT_EQ(wobble::whole_number(json::parse("0"), 0, 0), 0);
  EXPECT_EQ(wobble::whole_number(json::parse("18446744073709551615"), 0,
                                 std::numeric_limits<long long>::max()),
            std::nullopt);
  EXPECT_EQ(wobble::whole_number(json::parse("9007199254740992.0"), 0, 1LL << 53), 1LL << 53);
}

TEST(WholeNumber, FractionsAndOtherValuesAreNotWhole) {
  for (const char* text :
       {"10.5", "1e-1", "0.999999999", "\"10\"", "true", "null", "[10]", "{\"n\": 10}"}) {
    EXPECT_EQ(wobble::whole_number(json::parse(text), -100, 100), std::nullopt) << text;
  }
}

TEST(WholeNumber, OutOfRangeInAnySpelling) {
  for (const char* text : {"51", "51.0", "5.1e1", "1e300", "-1", "-1e300", "0", "1e19",
                           "18446744073709551615", "-9223372036854775808"}) {
    EXPECT_EQ(wobble::whole_number(json::parse(text), 1, 50), std::nullopt) << text;
  }
  // A huge double is refused, not converted (which would be undefined behaviour).
  EXPECT_EQ(wobble::whole_number(json::parse("1e300"), std::numeric_limits<long long>::min(),
                                 std::numeric_limits<long long>::max()),
            std::nullopt);
}

TEST(JsonPreview, ShortValuesWholeAndLongOnesCut) {
  EXPECT_EQ(wobble::json_preview(json::parse("[1, 2, 3]")), "[1,2,3]");
  EXPECT_EQ(wobble::json_preview(json::parse(R"({"a": [1.5, "x"]})")), R"({"a":[1.5,"x"]})");
  EXPECT_EQ(wobble::json_preview(json(std::string(100, 'y'))).size(), 40u);
  // A list of a million items is shown by its first few, without writing out the rest.
  const json many(std::vector<int>(1000000, 7));
  EXPECT_EQ(wobble::json_preview(many), "[7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,7,...");
  EXPECT_EQ(wobble::json_preview(json::parse("[[[[1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]]]]"), 20),
            "[[[[1,2,3,4,5,6,7...");
}

TEST(JsonFields, AllowOnlyNamesTheFirstUnknownKeyAndWhatIsTaken) {
  const json object = json::parse(R"({"k": 1, "dnsity": 2})");
  wobble::JsonFields fields("scene.json", object, "material");
  EXPECT_NO_THROW(fields.allow_only({"k", "dnsity"}, "material"));
  try {
    fields.allow_only({"k", "density"}, "material");
    FAIL() << "no error";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "scene.json: material.dnsity: unknown key, material takes k, density");
  }
}

}  // namespace
