/* Real-world method: Ray Tracing in One Weekend, v4 (camera::initialize),
 * converted to the kit: theta = degrees_to_radians(vfov) (deg * pi / 180
 * with the book's 20-digit pi), h = tan(theta / 2),
 * viewport_height = 2 h focal_length with the kit's d as the focal length,
 * viewport_width = viewport_height times the aspect ratio. */
#include "raytracer.h"

static const double pi = 3.1415926535897932385;

static double degrees_to_radians(double degrees)
{
    return degrees * pi / 180.0;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double focal_length = d;
    double theta = degrees_to_radians(fov_degrees);
    double half = tan(theta / 2);
    double viewport_height = 2 * half * focal_length;
    double viewport_width = viewport_height * aspect;
    *w = viewport_width;
    *h = viewport_height;
}
