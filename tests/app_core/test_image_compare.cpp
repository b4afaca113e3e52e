// `collide compare`'s arithmetic: which pixels differ, by how much, and the difference picture.

#include <doctest/doctest.h>

#include "image_compare.hpp"

using namespace collide;
using namespace collide::app;

TEST_CASE("compare_images counts pixels beyond the tolerance, and the largest difference") {
    Image a(4, 2);
    Image b(4, 2);
    CHECK(compare_images(a, b, 0).match());
    b.pixel(1, 0)[0] = 3;   // within a tolerance of 3
    b.pixel(2, 1)[3] = 40;  // alpha counts too
    b.pixel(3, 1)[2] = 200;
    const ImageComparison strict = compare_images(a, b, 0);
    CHECK(strict.pixels == 8);
    CHECK(strict.differing == 3);
    CHECK(strict.touched == 3);
    CHECK(strict.largest == 200);
    CHECK(strict.mean_differing == doctest::Approx((3 + 40 + 200) / 3.0));
    const ImageComparison tolerant = compare_images(a, b, 3);
    CHECK(tolerant.differing == 2);
    CHECK(tolerant.touched == 3);
    CHECK(!tolerant.match());
    CHECK(compare_images(a, b, 200).match());

    const Image diff = difference_image(a, b, 3);
    CHECK(diff.pixel(3, 1)[0] == 255);  // beyond: red
    CHECK(diff.pixel(3, 1)[1] == 0);
    CHECK(diff.pixel(1, 0)[1] == 200);  // within: yellow
    CHECK(diff.pixel(0, 0)[0] == 0);    // same: a's grey (black here)
    CHECK(diff.pixel(0, 0)[3] == 255);
}

TEST_CASE("compare_images: the bounding box of the differing pixels, and the allowances") {
    Image a(10, 6);
    Image b(10, 6);
    CHECK(compare_images(a, b, 0).differing_box.empty());
    b.pixel(7, 1)[1] = 50;
    b.pixel(2, 4)[0] = 9;
    b.pixel(5, 5)[2] = 2;  // within a tolerance of 2: outside the box then
    const ImageComparison c = compare_images(a, b, 2);
    CHECK(c.differing == 2);
    CHECK(c.differing_box.x0 == 2);
    CHECK(c.differing_box.y0 == 1);
    CHECK(c.differing_box.width() == 6);
    CHECK(c.differing_box.height() == 4);
    CHECK(c.differing_percent() == doctest::Approx(100.0 * 2 / 60));
    CompareAllowance allow;
    allow.tolerance = 2;
    CHECK(!within(c, allow));  // no allowance: no pixel may differ
    allow.max_pixels = 2;
    CHECK(within(c, allow));
    allow.max_percent = 3.0;  // 2 of 60 is 3.33 %
    CHECK(!within(c, allow));
    allow.max_percent = 100.0 * 2 / 60;
    CHECK(within(c, allow));
}
