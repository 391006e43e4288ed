// A plain copy: the memory bandwidth reference for the solver benchmarks.
__kernel void copy_float4(__global const float4* in, __global float4* out, int n) {
  int i = get_global_id(0);
  if (i >= n) return;
  out[i] = in[i];
}
