// vtkStylizeVolumeSurfaces over several processes (ParaView's ranks, each drawing its pieces of the
// same volumes): the whole image extents, the pieces' shared outer points and the fog's image.
#include "vtkStylizeVolumeSurfaces.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkStylizeVolumeFog.h"
#include "vtkStylizeVolumeSurface.h"
#include "vtkVolume.h"

#include <algorithm>
#include <array>
#include <string>

namespace
{
/**
 * The points along the longest side of the image the fog samples on several processes: data that
 * is not an image as on one process; an image too large to gather on its own grid, 128.
 */
int FogImagePoints(vtkDataSet* data)
{
  return vtkImageData::SafeDownCast(data) ? 128 : vtkStylizeVolumeFog::SampledPoints;
}
}

//------------------------------------------------------------------------------
std::vector<std::array<int, 6>> vtkStylizeVolumeSurfaces::WholeExtents(
  const std::vector<vtkProp*>& props, vtkMultiProcessController* c)
{
  std::vector<std::array<int, 6>> wholes;
  for (vtkProp* prop : props)
  {
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      std::array<int, 6> e = { VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX,
        VTK_INT_MIN };
      auto* image = volume->GetMapper()
        ? vtkImageData::SafeDownCast(UpdatedInput(volume->GetMapper()))
        : nullptr;
      if (image && image->GetNumberOfPoints() > 0)
      {
        image->GetExtent(e.data());
      }
      wholes.push_back(e);
    }
  }
  const int count = static_cast<int>(wholes.size());
  int least = count, most = count;
  if (c && c->GetNumberOfProcesses() > 1)
  {
    c->AllReduce(&count, &least, 1, vtkCommunicator::MIN_OP);
    c->AllReduce(&count, &most, 1, vtkCommunicator::MAX_OP);
  }
  if (!c || c->GetNumberOfProcesses() < 2 || least != most || count == 0)
  {
    wholes.assign(wholes.size(), { 0, -1, 0, -1, 0, -1 });
    return wholes;
  }
  // lows (minimum) and negated highs (minimum) in one reduction
  std::vector<int> local(6 * count), all(6 * count);
  for (int i = 0; i < count; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      local[6 * i + a] = wholes[i][2 * a];
      local[6 * i + 3 + a] =
        wholes[i][2 * a + 1] == VTK_INT_MIN ? VTK_INT_MAX : -wholes[i][2 * a + 1];
    }
  }
  c->AllReduce(
    local.data(), all.data(), static_cast<vtkIdType>(all.size()), vtkCommunicator::MIN_OP);
  for (int i = 0; i < count; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      wholes[i][2 * a] = all[6 * i + a];
      wholes[i][2 * a + 1] = all[6 * i + 3 + a] == VTK_INT_MAX ? VTK_INT_MIN : -all[6 * i + 3 + a];
    }
  }
  return wholes;
}

//------------------------------------------------------------------------------
std::vector<std::vector<vtkTypeUInt64>> vtkStylizeVolumeSurfaces::SharedPoints(
  vtkMultiProcessController* c)
{
  // This process's keys per volume (none for images: their extents close them), recomputed
  // only when the piece changed.
  std::vector<const std::vector<vtkTypeUInt64>*> local;
  std::map<vtkDataSet*, OuterKeys> kept;
  int changed = 0;
  const bool parallel = c && c->GetNumberOfProcesses() > 1;
  static const std::vector<vtkTypeUInt64> none;
  for (vtkProp* prop : this->Props)
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (!volume)
    {
      continue;
    }
    vtkDataSet* data =
      parallel && volume->GetMapper() ? UpdatedInput(volume->GetMapper()) : nullptr;
    if (!data || vtkImageData::SafeDownCast(data) || data->GetNumberOfCells() == 0)
    {
      local.push_back(&none);
      continue;
    }
    auto found = this->OuterKeyCache.find(data);
    OuterKeys& entry = kept[data];
    if (found != this->OuterKeyCache.end() && found->second.Time == data->GetMTime())
    {
      entry = std::move(found->second);
    }
    else
    {
      entry.Time = data->GetMTime();
      entry.Keys = vtkStylizeVolumeSurface::OuterPointKeys(data);
      changed = 1;
    }
    local.push_back(&entry.Keys);
  }
  changed = changed || kept.size() != this->OuterKeyCache.size();
  this->OuterKeyCache.swap(kept);
  std::vector<std::vector<vtkTypeUInt64>> shared(local.size());
  if (!parallel)
  {
    this->LastShared.clear();
    return shared;
  }
  // The same number of volumes on every process, else none (as the extents).
  const int count = static_cast<int>(local.size());
  int least = count, most = count, any = changed;
  c->AllReduce(&count, &least, 1, vtkCommunicator::MIN_OP);
  c->AllReduce(&count, &most, 1, vtkCommunicator::MAX_OP);
  if (least != most || count == 0)
  {
    this->LastShared.clear(); // (the next exchange is then due on every process)
    return shared;
  }
  // (every process decides alike whether to exchange: a collective call each makes, or none)
  changed = changed || this->LastShared.size() != local.size();
  c->AllReduce(&changed, &any, 1, vtkCommunicator::MAX_OP);
  if (!any)
  {
    return this->LastShared;
  }
  // Every process's keys, volume after volume: the lengths, then the keys.
  const int processes = c->GetNumberOfProcesses();
  const int rank = c->GetLocalProcessId();
  std::vector<vtkIdType> lengths(count), all(static_cast<size_t>(count) * processes);
  std::vector<unsigned long long> send;
  for (int v = 0; v < count; ++v)
  {
    lengths[v] = static_cast<vtkIdType>(local[v]->size());
    send.insert(send.end(), local[v]->begin(), local[v]->end());
  }
  c->AllGather(lengths.data(), all.data(), count);
  std::vector<vtkIdType> totals(processes, 0), offsets(processes, 0);
  for (int p = 0; p < processes; ++p)
  {
    for (int v = 0; v < count; ++v)
    {
      totals[p] += all[static_cast<size_t>(p) * count + v];
    }
    offsets[p] = p > 0 ? offsets[p - 1] + totals[p - 1] : 0;
  }
  std::vector<unsigned long long> received(offsets[processes - 1] + totals[processes - 1]);
  c->AllGatherV(send.data(), received.data(), static_cast<vtkIdType>(send.size()), totals.data(),
    offsets.data());
  for (int p = 0; p < processes; ++p)
  {
    vtkIdType at = offsets[p];
    for (int v = 0; v < count; ++v)
    {
      const vtkIdType n = all[static_cast<size_t>(p) * count + v];
      if (p != rank && !local[v]->empty())
      {
        shared[v].insert(shared[v].end(), received.begin() + at, received.begin() + at + n);
      }
      at += n;
    }
  }
  for (auto& keys : shared)
  {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  }
  this->LastShared = shared;
  return shared;
}

//------------------------------------------------------------------------------
std::vector<vtkImageData*> vtkStylizeVolumeSurfaces::FogImages(vtkMultiProcessController* c)
{
  std::vector<vtkVolume*> volumes;
  for (vtkProp* prop : this->Props)
  {
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      volumes.push_back(volume);
    }
  }
  std::vector<vtkImageData*> images(volumes.size(), nullptr);
  const int count = static_cast<int>(volumes.size());
  int least = count, most = count;
  if (!c || c->GetNumberOfProcesses() < 2)
  {
    this->GatheredImages.clear();
    return images;
  }
  c->AllReduce(&count, &least, 1, vtkCommunicator::MIN_OP);
  c->AllReduce(&count, &most, 1, vtkCommunicator::MAX_OP);
  if (least != most || count == 0)
  {
    this->GatheredImages.clear(); // (the processes disagree: no fog, the shell)
    return images;
  }
  std::map<vtkVolume*, Gathered> kept;
  for (size_t v = 0; v < volumes.size(); ++v)
  {
    vtkVolume* volume = volumes[v];
    vtkAbstractVolumeMapper* mapper = volume->GetMapper();
    vtkDataSet* data = mapper ? UpdatedInput(mapper) : nullptr;
    int cells = 0;
    vtkDataArray* scalars = data
      ? vtkAbstractMapper::GetScalars(data, mapper->GetScalarMode(), mapper->GetArrayAccessMode(),
          mapper->GetArrayId(), mapper->GetArrayName(), cells)
      : nullptr;
    // (gathered again when any piece or the array drawn changed: every process decides alike)
    auto found = this->GatheredImages.find(volume);
    const vtkMTimeType time = data ? data->GetMTime() : 0;
    const std::string name = scalars && scalars->GetName() ? scalars->GetName() : "";
    int changed = found == this->GatheredImages.end() || found->second.Time != time ||
      found->second.Name != name;
    int any = 0;
    c->AllReduce(&changed, &any, 1, vtkCommunicator::MAX_OP);
    Gathered& entry = kept[volume];
    if (any)
    {
      entry.Image = vtkStylizeVolumeFog::GatherImage(
        data, scalars ? scalars->GetName() : nullptr, c, FogImagePoints(data));
      entry.Time = time;
      entry.Name = name;
    }
    else
    {
      entry = found->second;
    }
    images[v] = entry.Image;
  }
  this->GatheredImages.swap(kept);
  return images;
}
