// fluidbed on a GPU: the per-cell entry points over a field of 4 Mi cells, one thread per cell,
// timed per cell with CUDA events beside the streaming limit of the same kernel shape (a kernel
// that reads and writes the same arrays and computes nothing), and checked against the host on
// the first 64 Ki cells (the largest relative difference of any output: for the eight-node
// inversion of broad distributions it measures the conditioning, not the device). Not a test (no assertion on time); run it where a GPU is lent, built as
//   nvcc -O3 -DNDEBUG -std=c++20 --expt-relaxed-constexpr -arch=sm_90 -Iinclude
//        -isystem /usr/include/eigen3 -diag-suppress 20012 bench/cuda/per_cell_timing.cu
// Cells: drag states spread wide, ε uniform in [0.36, 0.999] and Re = ρ_f w d/μ_f log-uniform in
// [1e-3, 1e4] (air, d = 300 µm); moments of log-normal size distributions, median 50–500 µm,
// σ_ln 0.2–1; kinetic theory at φ in [0.01, 0.6], Θ log-uniform in [1e-6, 1e-1] m² s⁻².
#include <cuda_runtime.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "fluidbed/fluidbed.hpp"

namespace {

using namespace fluidbed;

constexpr int cells = 1 << 22;
constexpr int checked_cells = 1 << 16;
constexpr int repeats = 20;
const Fluid<double> air{1.2, 1.8e-5};
constexpr double diameter = 3e-4;

#define CUDA_CHECK(call)                                                                        \
  do {                                                                                          \
    const cudaError_t status_ = (call);                                                         \
    if (status_ != cudaSuccess) {                                                               \
      std::printf("CUDA error %s at %s:%d\n", cudaGetErrorString(status_), __FILE__, __LINE__); \
      std::exit(1);                                                                             \
    }                                                                                           \
  } while (0)

// A field of `count` arrays of `cells` doubles on the device, with its host copy.
struct Arrays {
  int count;
  std::vector<double> host;
  double* device = nullptr;
  explicit Arrays(int count_) : count(count_), host(std::size_t(count_) * cells) {
    CUDA_CHECK(cudaMalloc(&device, host.size() * sizeof(double)));
  }
  ~Arrays() { cudaFree(device); }
  void upload() { CUDA_CHECK(cudaMemcpy(device, host.data(), host.size() * sizeof(double), cudaMemcpyHostToDevice)); }
  void download() {
    CUDA_CHECK(cudaMemcpy(host.data(), device, host.size() * sizeof(double), cudaMemcpyDeviceToHost));
  }
  double& at(int k, int c) { return host[std::size_t(k) * cells + c]; }
};

// cell(c, inputs, outputs) on every cell: what each timed kernel runs.
template <class Cell>
__global__ void over_cells(Cell cell, const double* in, double* out) {
  const int c = blockIdx.x * blockDim.x + threadIdx.x;
  if (c < cells) cell(c, in, out);
}

// The streaming limit: read `reads` arrays, write `writes`, compute nothing.
struct Stream {
  int reads, writes;
  FLUIDBED_HOST_DEVICE void operator()(int c, const double* in, double* out) const {
    double sum = 0;
    for (int k = 0; k < reads; ++k) sum += in[std::size_t(k) * cells + c];
    for (int k = 0; k < writes; ++k) out[std::size_t(k) * cells + c] = sum;
  }
};

template <class Cell>
float milliseconds_per_launch(const Cell& cell, const Arrays& in, Arrays& out) {
  const int threads = 256, blocks = (cells + threads - 1) / threads;
  over_cells<<<blocks, threads>>>(cell, in.device, out.device);  // warm-up
  CUDA_CHECK(cudaDeviceSynchronize());
  cudaEvent_t start, stop;
  CUDA_CHECK(cudaEventCreate(&start));
  CUDA_CHECK(cudaEventCreate(&stop));
  CUDA_CHECK(cudaEventRecord(start));
  for (int r = 0; r < repeats; ++r) over_cells<<<blocks, threads>>>(cell, in.device, out.device);
  CUDA_CHECK(cudaEventRecord(stop));
  CUDA_CHECK(cudaEventSynchronize(stop));
  CUDA_CHECK(cudaGetLastError());
  float ms = 0;
  CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
  cudaEventDestroy(start);
  cudaEventDestroy(stop);
  return ms / repeats;
}

// Times `cell` and the stream of its shape; checks the device's outputs against the host's on the
// first checked_cells cells (largest relative difference, scaled by the largest |value| of each
// output where a value is 0).
template <class Cell>
void report(const char* what, const Cell& cell, const Arrays& in, Arrays& out) {
  const float ms = milliseconds_per_launch(cell, in, out);
  out.download();
  std::vector<double> host_out(out.host.size());
  double worst = 0;
  for (int c = 0; c < checked_cells; ++c) {
    cell(c, in.host.data(), host_out.data());
    for (int k = 0; k < out.count; ++k) {
      const double h = host_out[std::size_t(k) * cells + c], d = out.at(k, c);
      const double difference = std::fabs(d - h) / std::max(std::fabs(h), 1e-300);
      worst = std::max(worst, std::isfinite(d) ? difference : INFINITY);
    }
  }
  Arrays sink(out.count);
  const float stream_ms = milliseconds_per_launch(Stream{in.count, out.count}, in, sink);
  std::printf("%-40s %8.3f ns/cell  %7.3f ns/cell streaming  %6.1fx  host %.1e\n", what, 1e6 * ms / cells,
              1e6 * stream_ms / cells, ms / stream_ms, worst);
}

template <class Law>
struct Beta {
  Law law;
  FLUIDBED_HOST_DEVICE void operator()(int c, const double* in, double* out) const {
    const drag::DragState<double> s{in[c], in[cells + c], {1.2, 1.8e-5}, diameter};
    out[c] = law(s).pressure_gradient();
  }
};

template <class Law>
struct BetaWithDerivatives {
  Law law;
  FLUIDBED_HOST_DEVICE void operator()(int c, const double* in, double* out) const {
    const drag::DragState<double> s{in[c], in[cells + c], {1.2, 1.8e-5}, diameter};
    const auto d = law.with_derivatives(s).pressure_gradient();
    out[c] = d.value;
    out[cells + c] = d.d_voidage;
    out[2 * std::size_t(cells) + c] = d.d_slip;
  }
};

template <int N>
struct Inversion {
  FLUIDBED_HOST_DEVICE void operator()(int c, const double* in, double* out) const {
    std::array<double, 2 * N> m{};
    for (int k = 0; k < 2 * N; ++k) m[k] = in[std::size_t(k) * cells + c];
    const auto r = moments::invert<N>(m);
    for (int i = 0; i < N; ++i) {
      out[std::size_t(i) * cells + c] = r.quadrature.nodes[i];
      out[std::size_t(N + i) * cells + c] = r.quadrature.weights[i];
    }
  }
};

struct KineticTheory {
  FLUIDBED_HOST_DEVICE void operator()(int c, const double* in, double* out) const {
    using namespace kinetic_theory;
    const ConstitutiveSet set{CarnahanStarling{}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
    const auto k = set.with_derivatives(in[c], in[cells + c], GranularMaterial<double>{3e-4, 2500.0, 0.9});
    out[c] = k.pressure.value;
    out[cells + c] = k.pressure.d_solid_fraction;
    out[2 * std::size_t(cells) + c] = k.shear_viscosity.value;
    out[3 * std::size_t(cells) + c] = k.shear_viscosity.d_granular_temperature;
  }
};

template <class Law>
void drag_rows(const char* name, const Law& law, const Arrays& states) {
  char what[64];
  Arrays beta(1), with(3);
  std::snprintf(what, sizeof what, "%s beta", name);
  report(what, Beta<Law>{law}, states, beta);
  std::snprintf(what, sizeof what, "%s beta and derivatives", name);
  report(what, BetaWithDerivatives<Law>{law}, states, with);
}

template <int N>
void inversion_row(std::mt19937_64& random) {
  Arrays moments(2 * N), rule(2 * N);
  std::uniform_real_distribution<double> median(std::log(50e-6), std::log(500e-6)), spread(0.2, 1.0);
  for (int c = 0; c < cells; ++c) {
    const double mu = median(random), sigma = spread(random);
    for (int k = 0; k < 2 * N; ++k) moments.at(k, c) = std::exp(k * mu + 0.5 * k * k * sigma * sigma);
  }
  moments.upload();
  char what[64];
  std::snprintf(what, sizeof what, "invert<%d> (log-normal cells)", N);
  report(what, Inversion<N>{}, moments, rule);
}

}  // namespace

int main() {
  int devices = 0;
  if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0) {
    std::printf("no CUDA device\n");
    return 77;
  }
  cudaDeviceProp properties{};
  CUDA_CHECK(cudaGetDeviceProperties(&properties, 0));
  std::printf("%s, %d cells, %d launches each, 256 threads per block\n", properties.name, cells, repeats);
  std::mt19937_64 random(2026);
  Arrays states(2);
  std::uniform_real_distribution<double> voidage(0.36, 0.999), log_reynolds(std::log(1e-3), std::log(1e4));
  for (int c = 0; c < cells; ++c) {
    states.at(0, c) = voidage(random);
    const double reynolds = std::exp(log_reynolds(random));  // ρ_f w d/μ_f
    states.at(1, c) = reynolds * air.viscosity / (air.density * diameter);
  }
  states.upload();
  drag_rows("WenYu1966", drag::ConstantExponentDrag::wen_yu_1966(), states);
  drag_rows("GidaspowSwitched", drag::GidaspowSwitched{}, states);
  drag_rows("DiFeliceDallavalle", drag::DiFelice<single_particle::DallavalleCoefficient>{}, states);
  drag_rows("Beetstra", drag::Beetstra{}, states);
  drag_rows("MazzeiLettieri", drag::MazzeiLettieri{}, states);
  inversion_row<3>(random);
  inversion_row<4>(random);
  inversion_row<8>(random);
  Arrays granular(2), constitutive(4);
  std::uniform_real_distribution<double> phi(0.01, 0.6), log_theta(std::log(1e-6), std::log(1e-1));
  for (int c = 0; c < cells; ++c) granular.at(0, c) = phi(random), granular.at(1, c) = std::exp(log_theta(random));
  granular.upload();
  report("kinetic theory set with derivatives", KineticTheory{}, granular, constitutive);
  return 0;
}
