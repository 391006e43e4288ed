#include "render/coating_tables.h"

#include <cstring>
#include <map>

#include "shared/coating_table.h"
#include "util/gauss_legendre.h"

namespace gdr {
namespace {

constexpr size_t kRows = 128;  // COATING_ROWS in coating_tables.cl: the larger rule's points

// The 32- and 128-point Gauss-Legendre rules on [0, 1], as coating_tables.cl reads them.
std::vector<cl_float2> coating_rules() {
  std::vector<cl_float2> rules;
  for (int n : {32, 128}) {
    GaussLegendre g = gauss_legendre(n, 0.0, 1.0);
    for (int i = 0; i < n; ++i) {
      cl_float2 v;
      v.s[0] = static_cast<float>(g.nodes[i]);
      v.s[1] = static_cast<float>(g.weights[i]);
      rules.push_back(v);
    }
  }
  return rules;
}

}  // namespace

std::array<uint32_t, 5> coating_key(const GdrMaterial& m) {
  std::array<uint32_t, 5> key{static_cast<uint32_t>(m.type), static_cast<uint32_t>(m.distribution)};
  std::memcpy(&key[2], &m.alpha_u, 4);
  std::memcpy(&key[3], &m.alpha_v, 4);
  std::memcpy(&key[4], &m.eta[0], 4);
  return key;
}

void build_coating_tables(Context& ctx, std::vector<GdrMaterial>& materials,
                          std::vector<float>& tables, const std::vector<bool>& needed) {
  std::vector<cl_int> jobs;
  std::map<std::array<uint32_t, 5>, int> block_of;
  size_t size = 0;
  for (size_t i = 0; i < materials.size(); ++i) {
    bool used = needed.empty() || (i < needed.size() && needed[i]);
    int n = used ? coating_table_size(materials[i].type) : 0;
    materials[i].coating_table = -1;
    if (n == 0) continue;
    auto [it, fresh] = block_of.emplace(coating_key(materials[i]), static_cast<int>(size));
    materials[i].coating_table = it->second;
    if (!fresh) continue;
    jobs.push_back(static_cast<cl_int>(i));
    size += static_cast<size_t>(n);
  }
  tables.assign(size, 0.0f);
  if (jobs.empty()) return;
  ScopedTimer timer(ctx.stats(), "scene/coating_tables");
  std::shared_ptr<Program> program = ctx.program("bsdf/coating_tables.cl");
  Buffer<GdrMaterial> material_buf(ctx, materials, CL_MEM_READ_ONLY);
  Buffer<cl_int> job_buf(ctx, jobs, CL_MEM_READ_ONLY);
  Buffer<cl_float2> rule_buf(ctx, coating_rules(), CL_MEM_READ_ONLY);
  const cl_uint job_count = static_cast<cl_uint>(jobs.size());
  const size_t items = jobs.size() * GDR_COATING_NODES * kRows;
  Buffer<cl_float2> partial(ctx, items);
  Buffer<float> table_buf(ctx, size);
  program->kernel("coating_partial_sums")
      .args(material_buf, job_buf, job_count, rule_buf, partial)
      .run(items);
  program->kernel("coating_finish")
      .args(material_buf, job_buf, job_count, partial, table_buf)
      .run(jobs.size());
  tables = table_buf.read();
}

}  // namespace gdr
