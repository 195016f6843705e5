/*
 * hold.c - hold a file open as most programs do, by fopen() (which on
 * Windows lets no other program delete or replace it), until standard
 * input ends: tests/windows.sh's program that has -o's target open.
 * Says "held" once it has it.
 */
#include <stdio.h>

int
main(int argc, char *argv[])
{
	FILE *fp;

	if (argc != 2 || (fp = fopen(argv[1], "rb")) == NULL) {
		fprintf(stderr, "usage: hold FILE (which must exist)\n");
		return 2;
	}
	puts("held");
	fflush(stdout);
	while (getchar() != EOF)
		continue;
	fclose(fp);
	return 0;
}
