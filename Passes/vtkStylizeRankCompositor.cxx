#include "vtkStylizeRankCompositor.h"

#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <algorithm>

namespace
{
const int ChannelTag = 735310; // and the next 6
}

vtkStandardNewMacro(vtkStylizeRankCompositor);
vtkCxxSetObjectMacro(vtkStylizeRankCompositor, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkStylizeRankCompositor::~vtkStylizeRankCompositor()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeRankCompositor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "Controller: " << (this->Controller ? this->Controller->GetNumberOfProcesses() : 1)
     << " process(es)\n";
}

//------------------------------------------------------------------------------
void vtkStylizeRankCompositor::Paste(
  Part& to, const Part& from, const std::vector<int>& components, bool nearer)
{
  for (int y = 0; y < from.Rect[3]; ++y)
  {
    for (int x = 0; x < from.Rect[2]; ++x)
    {
      const vtkIdType a = static_cast<vtkIdType>(y) * from.Rect[2] + x;
      const vtkIdType b = static_cast<vtkIdType>(y + from.Rect[1] - to.Rect[1]) * to.Rect[2] +
        (x + from.Rect[0] - to.Rect[0]);
      if (nearer && !(from.Depth[a] < to.Depth[b]))
      {
        continue;
      }
      to.Depth[b] = from.Depth[a];
      for (size_t c = 0; c < components.size(); ++c)
      {
        const int n = components[c];
        std::copy_n(&from.Channels[c][n * a], n, &to.Channels[c][n * b]);
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkStylizeRankCompositor::UnionRect(const int a[4], const int b[4], int out[4])
{
  const bool hasA = a[2] > 0 && a[3] > 0;
  const bool hasB = b[2] > 0 && b[3] > 0;
  if (!hasA || !hasB)
  {
    std::copy(hasA ? a : b, (hasA ? a : b) + 4, out);
    return;
  }
  out[0] = std::min(a[0], b[0]);
  out[1] = std::min(a[1], b[1]);
  out[2] = std::max(a[0] + a[2], b[0] + b[2]) - out[0];
  out[3] = std::max(a[1] + a[3], b[1] + b[3]) - out[1];
}

//------------------------------------------------------------------------------
void vtkStylizeRankCompositor::Merge(Part& own, Part& in, const std::vector<int>& components)
{
  if (in.Area() == 0)
  {
    return;
  }
  if (own.Area() == 0)
  {
    own = std::move(in);
    return;
  }
  Part u;
  UnionRect(own.Rect, in.Rect, u.Rect);
  u.Depth.assign(u.Area(), 1.0f);
  u.Channels.resize(components.size());
  for (size_t c = 0; c < components.size(); ++c)
  {
    u.Channels[c].assign(components[c] * u.Area(), 0.0f);
  }
  Paste(u, own, components, false);
  Paste(u, in, components, true);
  own = std::move(u);
}

//------------------------------------------------------------------------------
bool vtkStylizeRankCompositor::InsideImage(const int rect[4], int w, int h)
{
  return rect[0] >= 0 && rect[1] >= 0 && rect[2] >= 0 && rect[3] >= 0 && rect[0] + rect[2] <= w &&
    rect[1] + rect[3] <= h;
}

//------------------------------------------------------------------------------
bool vtkStylizeRankCompositor::Reduce(Part& own, const std::vector<int>& components, int w, int h)
{
  vtkMultiProcessController* controller = this->Controller;
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const int size = controller ? controller->GetNumberOfProcesses() : 1;
  const size_t channels = components.size();
  // A binary tree towards process 0: at step s, process r (r mod 2s = s) sends to r - s.
  for (int step = 1; step < size; step *= 2)
  {
    if (rank % (2 * step) == step)
    {
      const int to = rank - step;
      // A part the receiver would refuse (outside the image, or with fewer values than its
      // rectangle holds) is sent as an empty rectangle and no data: the receiver receives data
      // only for a part it keeps, so data sent anyway would be read as the next frame's. An
      // empty part (a process that drew nothing: a rank without data) is sent as it is.
      bool valid =
        InsideImage(own.Rect, w, h) && own.Depth.size() >= static_cast<size_t>(own.Area());
      for (size_t c = 0; c < channels && valid && own.Area() > 0; ++c)
      {
        valid = c < own.Channels.size() &&
          own.Channels[c].size() >= static_cast<size_t>(components[c] * own.Area());
      }
      if (!valid)
      {
        vtkErrorMacro("Process " << rank << " has channels outside the image: not sent.");
        std::fill(own.Rect, own.Rect + 4, 0);
      }
      controller->Send(own.Rect, 4, to, ChannelTag);
      if (own.Area() > 0)
      {
        controller->Send(own.Depth.data(), own.Area(), to, ChannelTag + 1);
        for (size_t c = 0; c < channels; ++c)
        {
          controller->Send(own.Channels[c].data(), components[c] * own.Area(), to,
            ChannelTag + 2 + static_cast<int>(c));
        }
      }
      return false;
    }
    if (rank + step < size)
    {
      const int from = rank + step;
      Part in;
      in.Channels.resize(channels);
      controller->Receive(in.Rect, 4, from, ChannelTag);
      if (!InsideImage(in.Rect, w, h))
      {
        vtkErrorMacro("Process " << from << " sent channels outside the image.");
        std::fill(in.Rect, in.Rect + 4, 0);
      }
      if (in.Area() > 0)
      {
        in.Depth.resize(in.Area());
        controller->Receive(in.Depth.data(), in.Area(), from, ChannelTag + 1);
        for (size_t c = 0; c < channels; ++c)
        {
          in.Channels[c].resize(components[c] * in.Area());
          controller->Receive(in.Channels[c].data(), components[c] * in.Area(), from,
            ChannelTag + 2 + static_cast<int>(c));
        }
      }
      Merge(own, in, components);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeRankCompositor::BroadcastDepth(Part& part, int w, int h)
{
  if (this->Controller)
  {
    this->Controller->Broadcast(part.Rect, 4, 0);
  }
  if (!InsideImage(part.Rect, w, h))
  {
    vtkErrorMacro("Process 0 sent a depth outside the image.");
    std::fill(part.Rect, part.Rect + 4, 0);
    return;
  }
  part.Depth.resize(part.Area());
  if (this->Controller && part.Area() > 0)
  {
    this->Controller->Broadcast(part.Depth.data(), part.Area(), 0);
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeRankCompositor::InFront(const double a[6], const double b[6], bool parallel,
  const double eye[3], const double direction[3])
{
  int axis = 0;
  bool aLow = true;
  double gap = -VTK_DOUBLE_MAX;
  for (int k = 0; k < 3; ++k)
  {
    const double below = b[2 * k] - a[2 * k + 1]; // a below b along k
    const double above = a[2 * k] - b[2 * k + 1]; // a above b
    if (below > gap)
    {
      gap = below;
      axis = k;
      aLow = true;
    }
    if (above > gap)
    {
      gap = above;
      axis = k;
      aLow = false;
    }
  }
  const double sizeA = a[2 * axis + 1] - a[2 * axis];
  const double sizeB = b[2 * axis + 1] - b[2 * axis];
  if (gap > -0.25 * std::min(sizeA, sizeB))
  {
    // (pieces of a partition share a layer of cells at most: the plane between them)
    const double plane =
      aLow ? 0.5 * (a[2 * axis + 1] + b[2 * axis]) : 0.5 * (b[2 * axis + 1] + a[2 * axis]);
    const bool lowInFront = parallel ? direction[axis] > 0.0 : eye[axis] < plane;
    return aLow == lowInFront;
  }
  double da = 0.0, db = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double ca = 0.5 * (a[2 * k] + a[2 * k + 1]);
    const double cb = 0.5 * (b[2 * k] + b[2 * k + 1]);
    if (parallel)
    {
      da += ca * direction[k];
      db += cb * direction[k];
    }
    else
    {
      da += (ca - eye[k]) * (ca - eye[k]);
      db += (cb - eye[k]) * (cb - eye[k]);
    }
  }
  return da < db;
}
