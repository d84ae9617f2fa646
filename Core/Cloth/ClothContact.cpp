#include "Cloth/ClothContact.h"

#include "Backend/ForEach.h"

namespace soak {

void resolveClothContacts(Device d, ParticleView p, GridView g, ClothView c, Vec3* delta, int passes) {
  for (int pass = 0; pass < passes; ++pass) {
    forEach(d, p.count, SOAK_LAMBDA(int i) {
      delta[i] = Vec3(0.f, 0.f, 0.f);
      const int phi = p.phase[i];
      const Float4 xi4 = p.predicted[i];
      if (!isCloth(phi) || xi4.w == 0.f) return;
      const Vec3 xi = xi4.xyz();
      const int vi = p.id[i];
      const Vec3 resti = c.restPosition[vi];
      const float thi = c.thickness[vi];
      Vec3 sum(0.f, 0.f, 0.f);
      int count = 0;
      forEachCandidate(g, g.cellKey[i], [&](int j) {
        const int phj = p.phase[j];
        if (j == i || !isCloth(phj)) return;
        const int vj = p.id[j];
        const float contact = 0.5f * (thi + c.thickness[vj]);
        const Float4 xj4 = p.predicted[j];
        const Vec3 xij = xi - xj4.xyz();
        // The pair's normal is taken from the positions at the start of the
        // step, so a fast layer cannot tunnel through and be pushed out the
        // wrong side.
        const Vec3 xij0 = p.position[i].xyz() - p.position[j].xyz();
        const float r0sq = lengthSquared(xij0);
        if (r0sq >= 4.f * contact * contact && lengthSquared(xij) >= contact * contact) return;
        if (phj == phi && lengthSquared(resti - c.restPosition[vj]) < 1.44f * contact * contact) return;
        const Vec3 n = r0sq > 1e-18f ? xij0 / sqrtf(r0sq) : normalizedOrZero(xij);
        const float along = dot(xij, n);
        if (along >= contact || lengthSquared(xij - n * along) >= contact * contact) return;
        sum += n * ((contact - along) * xi4.w / (xi4.w + xj4.w));
        ++count;
      });
      if (count > 0) delta[i] = sum / float(count);
    }, "cloth.contact");
    forEach(d, p.count, SOAK_LAMBDA(int i) {
      const Vec3 dx = delta[i];
      if (dx.x != 0.f || dx.y != 0.f || dx.z != 0.f) {
        const Float4 x = p.predicted[i];
        p.predicted[i] = Float4(x.xyz() + dx, x.w);
      }
    }, "cloth.contact.apply");
  }
}

}  // namespace soak
