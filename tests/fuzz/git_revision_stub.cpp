// The fuzz build has no build-time revision step; sidecars written by it (none are) would say so.
#include "renderer/git_revision.h"

const char* raylab::gitRevision() { return "fuzz"; }
