// The isolated read of vtkStylizeReader in a multithreaded host (issue 53): the helper program is
// started while vtkSMPTools' thread pool and a second thread allocate and free without pause, as
// ParaView's, Qt's and TBB's threads do beside a read. A fork() of such a process copies the
// locks those threads hold (allocator arenas, the pool's queues, VTK's output window): the child
// then waits forever on a lock no thread of its own will release. The exec'd helper starts with
// none of them. 200 reads of valid files of several formats must each give the data the same
// file gives when read in this process, within the reader's time limit.
#include "vtkStylizeReader.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace
{
struct Summary
{
  std::string Class;
  long long Points = -1;
  long long Cells = -1;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };

  bool operator==(const Summary& o) const
  {
    if (this->Class != o.Class || this->Points != o.Points || this->Cells != o.Cells)
    {
      return false;
    }
    for (int i = 0; i < 6; ++i)
    {
      if (this->Bounds[i] != o.Bounds[i])
      {
        return false;
      }
    }
    return true;
  }
};

Summary Read(const std::string& path, bool isolated, std::string& error)
{
  vtkNew<vtkStylizeReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetIsolated(isolated);
  reader->SetTimeLimit(20.0);
  reader->Update();
  error = reader->GetErrorMessage();
  Summary s;
  vtkDataObject* data = reader->GetOutputDataObject(0);
  if (!data || !error.empty())
  {
    return s;
  }
  s.Class = data->GetClassName();
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    s.Points = ds->GetNumberOfPoints();
    s.Cells = ds->GetNumberOfCells();
    ds->GetBounds(s.Bounds);
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    s.Points = cd->GetNumberOfPoints();
    s.Cells = cd->GetNumberOfCells();
  }
  return s;
}

/** Allocates and frees blocks of various sizes until stop (another thread of the host). */
void Churn(const std::atomic<bool>& stop, std::atomic<long long>& rounds)
{
  std::vector<std::unique_ptr<char[]>> held(64);
  for (std::size_t i = 0; !stop; ++i)
  {
    held[i % held.size()].reset(new char[16 + (i * 7919) % 65536]);
    held[i % held.size()][0] = static_cast<char>(i);
    ++rounds;
  }
}
} // namespace

int TestReaderThreadedHost(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: TestReaderThreadedHost DATA_FOLDER\n");
    return 1;
  }
  const std::string data = argv[1];
  const std::vector<std::string> files = { "sphere.vtp", "sphere_binary.vtk", "sphere.ply",
    "sphere_binary.stl", "sphere.obj", "hexes.vtu", "wavelet.vti", "grid.vtr", "sheet.vts",
    "blocks.vtm", "mesh.ex2", "series.pvd" };
  std::vector<Summary> expected;
  for (const std::string& f : files)
  {
    std::string error;
    expected.push_back(Read(data + "/" + f, false, error));
    if (!error.empty())
    {
      std::fprintf(stderr, "%s in process: %s\n", f.c_str(), error.c_str());
      return 1;
    }
  }

  int failures = 0;
  int reads = 0;
  // Every backend built into VTK, or the one VTK_SMP_BACKEND_IN_USE names (the ThreadSanitizer
  // stage's choice): 200 reads in all.
  std::vector<std::string> backends;
  const char* chosen = std::getenv("VTK_SMP_BACKEND_IN_USE");
  for (const char* backend : { "TBB", "STDThread", "Sequential" })
  {
    if ((!chosen || !*chosen || chosen == std::string(backend)) && vtkSMPTools::SetBackend(backend))
    {
      backends.emplace_back(backend);
    }
  }
  for (const std::string& name : backends)
  {
    const char* backend = name.c_str();
    vtkSMPTools::SetBackend(backend);
    std::atomic<bool> stop{ false };
    std::atomic<long long> churned{ 0 }, tasks{ 0 };
    // The pool: vtkSMPTools::For over chunks that allocate, again and again, from a thread
    // that is neither this one nor the churning one.
    std::thread pool(
      [&]()
      {
        while (!stop)
        {
          vtkSMPTools::For(0, 4096, 16,
            [&](vtkIdType begin, vtkIdType end)
            {
              std::vector<double> scratch(static_cast<std::size_t>(end - begin) * 97);
              scratch[0] = vtkMath::Pi();
              ++tasks;
            });
        }
      });
    std::thread churn(Churn, std::cref(stop), std::ref(churned));
    const auto start = std::chrono::steady_clock::now();
    const int count = backends.size() == 1 ? 200 : name == "Sequential" ? 40 : 80;
    for (int i = 0; i < count; ++i, ++reads)
    {
      const std::size_t k = static_cast<std::size_t>(i) % files.size();
      std::string error;
      const Summary got = Read(data + "/" + files[k], true, error);
      if (!error.empty() || !(got == expected[k]))
      {
        std::fprintf(stderr, "%s, read %d of %s: %s\n", backend, i, files[k].c_str(),
          error.empty() ? "the data differs from the read in process" : error.c_str());
        ++failures;
      }
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stop = true;
    pool.join();
    churn.join();
    std::printf("%s: %d isolated reads in %.1f s (%.0f ms each) beside %lld pool tasks and %lld "
                "allocations\n",
      backend, count, seconds, 1000.0 * seconds / count, static_cast<long long>(tasks),
      static_cast<long long>(churned));
    if (tasks == 0 || churned == 0)
    {
      std::fprintf(stderr, "%s: the other threads did not run\n", backend);
      ++failures;
    }
  }
  std::printf("%d reads, %d failures\n", reads, failures);
  if (reads < 200)
  {
    std::fprintf(stderr, "only %d reads (fewer than 200: a backend is missing)\n", reads);
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
