/* povwords.h - is an identifier one of POV-Ray's reserved words? */
#ifndef POVWORDS_H
#define POVWORDS_H

int	pov_reserved(const char *);

#endif
