/* Constants that strict C11 <math.h> does not provide. */
#ifndef FULGUR_FG_MATH_INTERNAL_H
#define FULGUR_FG_MATH_INTERNAL_H

#define FG_PI 3.14159265358979323846

#endif
