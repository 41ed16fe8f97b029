// certbox from C++ (C++11): certbox.h is a C header with extern "C", so a
// C++ program includes it as it is and links libcertbox.  make install-check
// builds this file with g++ -std=c++11 -Wall -Wextra -Wpedantic -Werror
// against a staged install (pkg-config, and CMake's certbox::certbox) and
// runs it: it prints the box of a rotated, moved cube and of an ellipsoid,
// and checks that the cube's eight corner images lie in the box.
#include <certbox.h>

#include <cmath>
#include <cstdio>

int main()
{
    const double c = std::sqrt(0.5);  // cos 45 degrees = sin 45 degrees
    // rotation by 45 degrees about z, then a move by (1, 2, 3)
    const cbx_affine a = {{{c, -c, 0, 1}, {c, c, 0, 2}, {0, 0, 1, 3}}};
    const cbx_box cube = {{-1, -1, -1}, {1, 1, 1}};
    cbx_box out;
    const cbx_status s = cbx_transform_box(&a, &cube, &out);
    std::printf("cube:      %s lo %.17g %.17g %.17g hi %.17g %.17g %.17g\n", cbx_status_name(s),
                out.lo[0], out.lo[1], out.lo[2], out.hi[0], out.hi[1], out.hi[2]);

    // the corners, mapped in floating point: each coordinate is within a
    // rounding error of the exact image, which the box contains with margin
    int outside = 0;
    for (int k = 0; k < 8; ++k) {
        const double x[3] = {(k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0};
        for (int i = 0; i < 3; ++i) {
            const double y = a.m[i][0] * x[0] + a.m[i][1] * x[1] + a.m[i][2] * x[2] + a.m[i][3];
            if (!(out.lo[i] <= y && y <= out.hi[i])) {
                ++outside;
            }
        }
    }

    // an ellipsoid: centre, radii and a rotation (C++ converts double[3][3]
    // to const double (*)[3] by itself)
    const double centre[3] = {0, 0, 10};
    const double radii[3] = {2, 1, 0.5};
    const double rot[3][3] = {{c, -c, 0}, {c, c, 0}, {0, 0, 1}};
    cbx_box ell;
    const cbx_status t = cbx_ellipsoid_box(centre, radii, rot, &ell);
    std::printf("ellipsoid: %s lo %.17g %.17g %.17g hi %.17g %.17g %.17g\n", cbx_status_name(t),
                ell.lo[0], ell.lo[1], ell.lo[2], ell.hi[0], ell.hi[1], ell.hi[2]);

    const unsigned ieee = cbx_ieee_check();
    std::printf("certbox %s from C++: %d corner coordinates outside the box; ieee check %u\n",
                CBX_VERSION_STRING, outside, ieee);
    return (s == CBX_OK && t == CBX_OK && outside == 0 && ieee == 0) ? 0 : 1;
}
