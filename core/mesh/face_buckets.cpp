#include "core/mesh/face_buckets.h"

#include <algorithm>

namespace cvtmesh {

void sort_face_buckets(FaceBuckets& fb) {
  const long n = static_cast<long>(fb.nb_buckets());
#pragma omp parallel for schedule(dynamic, 4096) if (n > 4096)
  for (long a = 0; a < n; ++a)
    std::sort(fb.records.begin() + static_cast<std::ptrdiff_t>(fb.start[a]),
              fb.records.begin() + static_cast<std::ptrdiff_t>(fb.start[a + 1]));
}

}  // namespace cvtmesh
