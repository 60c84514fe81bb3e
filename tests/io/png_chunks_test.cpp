#include "io/png_chunks.h"

#include <gtest/gtest.h>

#include <string>

#include "png_bytes.h"

namespace {

using wobble::testing::png_chunk;

std::string signature() {
  return std::string("\x89PNG\r\n\x1a\n", 8);
}

// What PngChunks finds in `bytes`, fed `step` bytes at a time, then the end of the file.
std::string damage_of(const std::string& bytes, std::size_t step, bool* complete = nullptr) {
  wobble::PngChunks chunks;
  for (std::size_t at = 0; at < bytes.size(); at += step) {
    const std::string part = bytes.substr(at, step);
    chunks.feed(reinterpret_cast<const unsigned char*>(part.data()), part.size());
  }
  chunks.end_of_file();
  if (complete) *complete = chunks.complete();
  return chunks.damage();
}

TEST(Crc32, MatchesTheStandardCheckValue) {
  const std::string text = "123456789";
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  EXPECT_EQ(wobble::crc32_update(0, bytes, text.size()), 0xCBF43926u);
  // In two parts, continuing from the first.
  EXPECT_EQ(wobble::crc32_update(wobble::crc32_update(0, bytes, 4), bytes + 4, 5), 0xCBF43926u);
  EXPECT_EQ(wobble::testing::png_crc32(text), 0xCBF43926u);  // the tests' own encoder agrees
}

TEST(PngChunks, AWholeFileIsCompleteHoweverItIsHandedOver) {
  const std::string file = signature() + png_chunk("IHDR", std::string(13, '\1')) +
                           png_chunk("IDAT", "pixels") + png_chunk("IEND", "");
  for (const std::size_t step : {std::size_t{1}, std::size_t{3}, std::size_t{8}, file.size()}) {
    bool complete = false;
    EXPECT_EQ(damage_of(file, step, &complete), "") << step;
    EXPECT_TRUE(complete) << step;
  }
  // Bytes after IEND are not looked at.
  bool complete = false;
  EXPECT_EQ(damage_of(file + "junk", 5, &complete), "");
  EXPECT_TRUE(complete);
}

TEST(PngChunks, NamesTheChunkThatIsDamagedOrCut) {
  const std::string ihdr = png_chunk("IHDR", std::string(13, '\1'));
  const std::string idat = png_chunk("IDAT", "pixels");
  const std::string iend = png_chunk("IEND", "");
  const auto flipped = [](std::string chunk, std::size_t at) {
    chunk[at] ^= 0x20;
    return chunk;
  };
  const std::string head = signature() + ihdr;
  // The type counts: a chunk renamed without a new CRC is damaged.
  EXPECT_EQ(damage_of(head + flipped(idat, 4) + iend, 7), "chunk iDAT checksum is wrong");
  EXPECT_EQ(damage_of(head + flipped(idat, 9) + iend, 7), "chunk IDAT checksum is wrong");
  EXPECT_EQ(damage_of(head + flipped(idat, idat.size() - 1) + iend, 2),
            "chunk IDAT checksum is wrong");
  EXPECT_EQ(damage_of(head + idat + flipped(iend, 11), 1), "chunk IEND checksum is wrong");
  // Only the first damage is kept.
  EXPECT_EQ(damage_of(signature() + flipped(ihdr, 20) + flipped(idat, 9) + iend, 4),
            "chunk IHDR checksum is wrong");
  EXPECT_EQ(damage_of(head + idat.substr(0, 10), 3), "the file ends inside chunk IDAT");
  EXPECT_EQ(damage_of(head + idat.substr(0, idat.size() - 1), 3),
            "the file ends inside chunk IDAT");
  EXPECT_EQ(damage_of(head + idat.substr(0, 5), 3),
            "the file ends inside a chunk's length and type");
  EXPECT_EQ(damage_of(head + idat, 3), "the file ends after chunk IDAT, without the IEND chunk");
  EXPECT_EQ(damage_of(signature(), 3), "the file ends after the PNG signature, without any chunk");
  // A type that is not four letters is shown with '?' for what is not a letter.
  EXPECT_EQ(damage_of(head + flipped(png_chunk("a\nb1", "x"), 9) + iend, 5),
            "chunk a?b? checksum is wrong");
}

TEST(PngChunks, WhatIsNotAPngIsLeftToTheDecoder) {
  bool complete = true;
  EXPECT_EQ(damage_of("GIF89a and more", 4, &complete), "");
  EXPECT_FALSE(complete);
  EXPECT_EQ(damage_of(signature().substr(0, 5), 4, &complete), "");
  EXPECT_FALSE(complete);
  // A length above 2^31 - 1 is not PNG either.
  EXPECT_EQ(damage_of(signature() + std::string("\x80\0\0\0IDAT", 8), 4, &complete), "");
  EXPECT_FALSE(complete);
}

}  // namespace
