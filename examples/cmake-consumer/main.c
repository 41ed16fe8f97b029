/* A C program built against an installed certbox: by CMake (find_package,
 * certbox::certbox or certbox::certbox_static; CMakeLists.txt here) and by
 * make install-check with pkg-config.  One box in each family, and the
 * build check; prints what it got and exits 0 when all is well. */
#include <certbox.h>
#include <stdio.h>

int main(void)
{
    const cbx_affine a = {{{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}}};
    const cbx_box b = {{0, 0, 0}, {1, 1, 1}};
    const cbx_affinef af = {{{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}}};
    const cbx_boxf bf = {{0, 0, 0}, {1, 1, 1}};
    cbx_box o;
    cbx_boxf of;
    cbx_status s = cbx_transform_box(&a, &b, &o);
    cbx_status t = cbx_transform_boxf(&af, &bf, &of);
    unsigned c = cbx_ieee_check();

    printf("certbox %s: %s [%g, %g]; %s [%g, %g]; ieee %u\n", CBX_VERSION_STRING,
           cbx_status_name(s), o.lo[0], o.hi[0], cbx_status_name(t), (double)of.lo[0],
           (double)of.hi[0], c);
    return (s == CBX_OK && t == CBX_OK && c == 0) ? 0 : 1;
}
