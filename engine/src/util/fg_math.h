/* Numbers C11 leaves out. */
#ifndef FG_MATH_H
#define FG_MATH_H

/* C11 has no M_PI. */
#define FG_PI 3.14159265358979323846

#endif
