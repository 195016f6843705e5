/*
 * test_scene.c - the scene loader: text need not end in NUL.  Each
 * check prints "ok - what" or "not ok - what"; tests/run.sh counts them.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"
#include "check.h"

/*
 * Found by fuzz_scene: a number at the very end of a buffer that is
 * not NUL-terminated was scanned past its end.  Under check-asan an
 * over-read of this exact-size heap copy fails the run.
 */
static void
test_unterminated(void)
{
	static const char crash[] = "model 102\273\ncyli= [0";
	static const struct {
		const char	*text;
		int		 rc;
		long long	 count;	/* as read from the last bytes */
	} t[] = {
		{ crash, -1, 0 },
		{ "model = \"planar\";\ncount = 12", 0, 12 },
		{ "model = \"planar\"; count = 0x1F", 0, 31 },
	};

	for (size_t i = 0; i < sizeof(t) / sizeof(t[0]); i++) {
		size_t len = strlen(t[i].text);
		char *buf = malloc(len);
		struct scene sc;
		int rc;

		memcpy(buf, t[i].text, len);
		rc = scene_load_buffer(&sc, "t.cfg", buf, len);
		check(rc == t[i].rc && (rc != 0 || sc.count == t[i].count),
		    "scene text need not end in NUL: text %zu %s (fuzz_scene "
		    "regression)", i + 1, t[i].rc ? "refused" : "read to its "
		    "last digit");
		scene_free(&sc);
		free(buf);
	}
}

int
main(void)
{
	test_unterminated();
	return check_failures != 0;
}
