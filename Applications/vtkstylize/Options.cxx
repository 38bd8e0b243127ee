// vtkstylize: the command line (CLI11), the styles, --help.
#include "Options.h"

#include "vtkstylizeCommon.h"

#include "vtkComicPass.h"
#include "vtkLineArtPass.h"
#include "vtkNew.h"
#include "vtkPixelArtPass.h"
#include "vtkSketchPass.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#ifndef VTKSTYLIZE_VERSION
#define VTKSTYLIZE_VERSION "unknown"
#endif

namespace vtkstylize
{
namespace
{
//------------------------------------------------------------------------------
// Values

/** A finite double that takes the whole string. */
bool ParseDouble(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

/** A decimal integer that takes the whole string. */
bool ParseInt(const std::string& text, long& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno != ERANGE;
}

std::vector<std::string> Split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true)
  {
    const auto pos = text.find(separator, start);
    parts.push_back(text.substr(start, pos - start));
    if (pos == std::string::npos)
    {
      return parts;
    }
    start = pos + 1;
  }
}

/** "R,G,B" with components in [0, 1], or "#rrggbb"; empty optional when malformed. */
std::optional<std::array<double, 3>> ParseColor(const std::string& v)
{
  std::array<double, 3> c{};
  if (!v.empty() && v[0] == '#')
  {
    if (v.size() != 7 || v.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
    {
      return std::nullopt;
    }
    for (int i = 0; i < 3; ++i)
    {
      c[i] = std::stoi(v.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
    }
    return c;
  }
  const auto parts = Split(v, ',');
  if (parts.size() != 3)
  {
    return std::nullopt;
  }
  for (int i = 0; i < 3; ++i)
  {
    if (!ParseDouble(parts[i], c[i]) || c[i] < 0.0 || c[i] > 1.0)
    {
      return std::nullopt;
    }
  }
  return c;
}

/** The colours of a --colors list: separated by ';' or white space (hex ones also by ','). */
std::vector<std::array<double, 3>> ParseColorList(const std::string& v, std::string& error)
{
  std::string list = v;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const bool hexComma = list[i] == ',' && i + 1 < list.size() && list[i + 1] == '#';
    if (list[i] == ';' || std::isspace(static_cast<unsigned char>(list[i])) || hexComma)
    {
      list[i] = ' ';
    }
  }
  std::vector<std::array<double, 3>> colours;
  std::istringstream words(list);
  std::string part;
  while (words >> part)
  {
    const auto c = ParseColor(part);
    if (!c)
    {
      error = "invalid colour " + Quote(part) + ": expected #rrggbb or R,G,B in [0, 1]";
      return {};
    }
    colours.push_back(*c);
  }
  if (colours.empty())
  {
    error = "no colour given";
  }
  else if (colours.size() > 256)
  {
    error = "at most 256 colours";
  }
  return colours;
}

std::string FormatValue(double v)
{
  return FormatNumber(v);
}
std::string FormatValue(int v)
{
  return std::to_string(v);
}
std::string FormatValue(bool v)
{
  return v ? "on" : "off";
}

//------------------------------------------------------------------------------
// Validators (CLI11): each checks one value and says what is wrong

/** A finite number (integer when `integer`) in [lo, hi]. */
CLI::Validator NumberIn(double lo, double hi, bool integer)
{
  const std::string range = std::isfinite(lo) && std::isfinite(hi)
    ? "[" + FormatNumber(lo) + ", " + FormatNumber(hi) + "]"
    : std::string("finite");
  return CLI::Validator(
    [=](std::string& text) -> std::string
    {
      double v = 0.0;
      long i = 0;
      if (integer ? !ParseInt(text, i) : !ParseDouble(text, v))
      {
        return "invalid value " + Quote(text) + ": expected " +
          (integer ? "an integer" : "a finite number");
      }
      if (integer)
      {
        v = static_cast<double>(i);
      }
      if (v < lo || v > hi)
      {
        return text + " is out of range " + range;
      }
      return std::string();
    },
    range);
}

/** COUNT comma-separated numbers, each in [lo, hi]. */
CLI::Validator NumbersIn(int count, double lo, double hi, const std::string& metavar)
{
  return CLI::Validator(
    [=](std::string& text) -> std::string
    {
      const auto parts = Split(text, ',');
      double v = 0.0;
      if (static_cast<int>(parts.size()) != count)
      {
        return "invalid value " + Quote(text) + ": expected " + metavar;
      }
      for (const std::string& p : parts)
      {
        if (!ParseDouble(p, v) || v < lo || v > hi)
        {
          return "invalid value " + Quote(text) + ": each of " + metavar + " must be in [" +
            FormatNumber(lo) + ", " + FormatNumber(hi) + "]";
        }
      }
      return std::string();
    },
    "each in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "]");
}

const CLI::Validator Color(
  [](std::string& text) -> std::string
  {
    return ParseColor(text)
      ? std::string()
      : "invalid colour " + Quote(text) + ": expected #rrggbb or R,G,B in [0, 1]";
  },
  "R,G,B in [0, 1] or #rrggbb");

/** One of `keywords`, case-insensitive (the value is lower-cased). */
CLI::Validator OneOf(const std::vector<std::string>& keywords)
{
  std::string list;
  for (const auto& k : keywords)
  {
    list += (list.empty() ? "" : ", ") + k;
  }
  return CLI::Validator(
    [=](std::string& text) -> std::string
    {
      const std::string l = Lower(text);
      if (std::find(keywords.begin(), keywords.end(), l) == keywords.end())
      {
        return "unknown value " + Quote(text) + " (expected " + list + ")";
      }
      text = l;
      return std::string();
    },
    "");
}

std::vector<double> ParseNumbers(const std::string& text)
{
  std::vector<double> out;
  for (const std::string& p : Split(text, ','))
  {
    double v = 0.0;
    ParseDouble(p, v);
    out.push_back(v);
  }
  return out;
}

//------------------------------------------------------------------------------
// The option table

/** A default-constructed pass of each class: the ranges and defaults shown in --help. */
template <class Pass>
Pass* Defaults()
{
  static vtkNew<Pass> pass;
  return pass;
}

/**
 * The --help group of a pass class's options, and the --style they apply to (none for the
 * lighting: every style).
 */
struct PassGroup
{
  const char* Group;
  const char* Style;
};
PassGroup GroupOf(const vtkStylizeLightingPass*)
{
  return { "Lighting", nullptr };
}
PassGroup GroupOf(const vtkComicPass*)
{
  return { "Comic (--style comic)", "comic" };
}
PassGroup GroupOf(const vtkPixelArtPass*)
{
  return { "Pixel art (--style pixel)", "pixel" };
}
PassGroup GroupOf(const vtkSketchPass*)
{
  return { "Sketch (--style sketch)", "sketch" };
}
PassGroup GroupOf(const vtkLineArtPass*)
{
  return { "Line art (--style lines)", "lines" };
}

/**
 * The options of the program on a CLI11 app. Each option has actions that run, for each
 * occurrence, in command-line order (Apply()). An option several pass classes share (e.g.
 * --depth-threshold for comic and pixel art) is one option with an action and a check per class.
 */
class OptionTable
{
public:
  using Action = std::function<void(Options&, const std::string&)>;

  explicit OptionTable(CLI::App& app)
    : App(app)
  {
  }

  /** An option that takes a value. */
  CLI::Option* Value(const std::string& name, const std::string& metavar, const std::string& help,
    const std::string& group, Action action)
  {
    return this->Add(name, metavar, help, group, std::move(action));
  }

  /** An option without a value. */
  CLI::Option* Flag(
    const std::string& name, const std::string& help, const std::string& group, Action action)
  {
    return this->Add(name, std::string(), help, group, std::move(action));
  }

  /** A numeric setting of a pass: range and default from the class. */
  template <class Pass, class T>
  void Number(const std::string& name, const std::string& metavar, const std::string& help,
    T (Pass::*min)(), T (Pass::*max)(), T (Pass::*get)(), void (Pass::*set)(T))
  {
    Pass* d = Defaults<Pass>();
    const T lo = (d->*min)(), hi = (d->*max)();
    // An option two styles share checks its range once (the styles' ranges are the same).
    const bool shared = this->Entries.count(name) != 0;
    CLI::Option* o = this->PassOption<Pass>(name, metavar, help, FormatValue((d->*get)()),
      [set](Pass* p, const std::string& v)
      {
        double x = 0.0;
        long i = 0;
        if (std::is_integral<T>::value && ParseInt(v, i))
        {
          x = static_cast<double>(i);
        }
        else
        {
          ParseDouble(v, x);
        }
        (p->*set)(static_cast<T>(x));
      });
    if (!shared)
    {
      o->check(NumberIn(lo, hi, std::is_integral<T>::value));
    }
  }

  /** An on/off setting of a pass: the option sets it to `value`. */
  template <class Pass>
  void Flag(const std::string& name, const std::string& help, void (Pass::*set)(bool),
    bool (Pass::*get)(), bool value)
  {
    this->PassOption<Pass>(name, std::string(), help, FormatValue((Defaults<Pass>()->*get)()),
      [set, value](Pass* p, const std::string&) { (p->*set)(value); });
  }

  /** An enumerated setting of a pass: case-insensitive keywords and their values. */
  template <class Pass>
  void Keywords(const std::string& name, const std::string& metavar, const std::string& help,
    int (Pass::*get)(), void (Pass::*set)(int),
    const std::vector<std::pair<std::string, int>>& words)
  {
    std::vector<std::string> keys;
    std::string current;
    const int value = (Defaults<Pass>()->*get)();
    for (const auto& w : words)
    {
      keys.push_back(w.first);
      if (w.second == value && current.empty())
      {
        current = w.first;
      }
    }
    CLI::Option* o = this->PassOption<Pass>(name, metavar, help, current,
      [set, words](Pass* p, const std::string& v)
      {
        for (const auto& w : words)
        {
          if (w.first == v)
          {
            (p->*set)(w.second);
          }
        }
      });
    o->transform(OneOf(keys));
  }

  /** A setting of COUNT numbers, each in [lo, hi], given as a comma list. */
  template <class Pass, class Setter>
  void Vector(const std::string& name, const std::string& metavar, const std::string& help,
    int count, double lo, double hi, const std::string& defaults, Setter set)
  {
    CLI::Option* o = this->PassOption<Pass>(name, metavar, help, defaults,
      [set](Pass* p, const std::string& v) { set(p, ParseNumbers(v)); });
    o->check(NumbersIn(count, lo, hi, metavar));
  }

  /** An RGB setting: R,G,B in [0, 1] or #rrggbb. */
  template <class Pass>
  void Colour(const std::string& name, const std::string& metavar, const std::string& help,
    const double* defaults, void (Pass::*set)(double, double, double))
  {
    CLI::Option* o = this->PassOption<Pass>(name, metavar, help,
      FormatNumber(defaults[0]) + "," + FormatNumber(defaults[1]) + "," + FormatNumber(defaults[2]),
      [set](Pass* p, const std::string& v)
      {
        const auto c = *ParseColor(v);
        (p->*set)(c[0], c[1], c[2]);
      });
    o->check(Color);
  }

  /** Adds an action to an existing option. */
  void Also(const std::string& name, Action action, const char* style = nullptr)
  {
    Entry& e = this->Entries.at(name);
    e.Actions.push_back(std::move(action));
    if (style)
    {
      e.Styles.insert(style);
    }
  }

  /** Runs the actions of every occurrence, in command-line order. */
  void Apply(Options& opt)
  {
    std::map<const CLI::Option*, size_t> seen;
    for (const CLI::Option* o : this->App.parse_order())
    {
      const auto entry = this->ByOption.find(o);
      if (entry == this->ByOption.end())
      {
        continue;
      }
      const size_t n = seen[o]++;
      const std::vector<std::string>& results = o->results();
      const std::string value = n < results.size() ? results[n] : std::string();
      for (const Action& action : entry->second->Actions)
      {
        action(opt, value);
      }
    }
    // Options of a style other than the chosen one do nothing: say so, once per option.
    for (const auto& e : this->Entries)
    {
      const Entry& entry = e.second;
      if (entry.Styles.empty() || entry.Option->count() == 0 || entry.Styles.count(opt.Style))
      {
        continue;
      }
      std::string styles;
      for (const std::string& st : entry.Styles)
      {
        styles += (styles.empty() ? "" : "|") + st;
      }
      opt.Warnings.push_back(
        e.first + " applies to --style " + styles + ", not " + opt.Style + " (ignored)");
    }
  }

private:
  struct Entry
  {
    CLI::Option* Option = nullptr;
    std::string Help;
    std::vector<Action> Actions;
    std::set<std::string> Styles; // the styles a pass option applies to; empty: every one
    /** A pass option's help per style, "style: text": the styles with the same text share it
     * ("comic, lines: text"). */
    std::vector<std::pair<std::string, std::string>> Parts;
  };

  /** "style: text" split at the first ": " (no style: all of it is the text). */
  static std::pair<std::string, std::string> SplitStyle(const std::string& help)
  {
    const size_t colon = help.find(": ");
    const bool styled =
      colon != std::string::npos && colon < 16 && help.find_first_of(" ,(") > colon;
    return styled ? std::make_pair(help.substr(0, colon), help.substr(colon + 2))
                  : std::make_pair(std::string(), help);
  }

  /** The help of a pass option from its parts. */
  static std::string JoinParts(const Entry& e)
  {
    std::string help;
    for (const auto& part : e.Parts)
    {
      help +=
        (help.empty() ? "" : "; ") + (part.first.empty() ? "" : part.first + ": ") + part.second;
    }
    return help;
  }

  CLI::Option* Add(const std::string& name, const std::string& metavar, const std::string& help,
    const std::string& group, Action action)
  {
    CLI::Option* o = nullptr;
    if (metavar.empty())
    {
      o = this->App.add_flag(name, help)->disable_flag_override();
    }
    else
    {
      o = this->App.add_option(name, help)->type_name(metavar);
      // TakeAll keeps every occurrence so that Apply() replays them in order (the last wins).
      o->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->expected(1);
    }
    o->group(group);
    Entry& e = this->Entries[name];
    e.Option = o;
    e.Help = help;
    e.Actions.push_back(std::move(action));
    this->ByOption[o] = &e;
    return o;
  }

  /** An option that sets a pass setting (or an existing one that also does). */
  template <class Pass>
  CLI::Option* PassOption(const std::string& name, const std::string& metavar,
    const std::string& help, const std::string& defaults,
    std::function<void(Pass*, const std::string&)> set)
  {
    const std::string text = help + (defaults.empty() ? "" : " (default: " + defaults + ")");
    Action action = [set](Options& opt, const std::string& v)
    { opt.Passes.Of<Pass>().push_back([set, v](Pass* p) { set(p, v); }); };
    auto found = this->Entries.find(name);
    if (found == this->Entries.end())
    {
      CLI::Option* o =
        this->Add(name, metavar, text, GroupOf(static_cast<Pass*>(nullptr)).Group, action);
      Entry& e = this->Entries[name];
      e.Parts.push_back(SplitStyle(text));
      if (const char* style = GroupOf(static_cast<Pass*>(nullptr)).Style)
      {
        e.Styles.insert(style);
      }
      return o;
    }
    Entry& e = found->second;
    if (const char* style = GroupOf(static_cast<Pass*>(nullptr)).Style)
    {
      e.Styles.insert(style);
    }
    // (a setting of the style base, alike in several styles, is described once)
    const auto part = SplitStyle(text);
    auto same = std::find_if(e.Parts.begin(), e.Parts.end(),
      [&](const std::pair<std::string, std::string>& p) { return p.second == part.second; });
    if (same != e.Parts.end() && !part.first.empty() && !same->first.empty())
    {
      same->first += ", " + part.first;
    }
    else
    {
      e.Parts.push_back(part);
    }
    e.Help = JoinParts(e);
    e.Option->description(e.Help);
    e.Actions.push_back(action);
    return e.Option;
  }

  CLI::App& App;
  std::map<std::string, Entry> Entries;
  std::map<const CLI::Option*, Entry*> ByOption;
};

/** Calls f(v[0], ..., v[N-1]). */
template <class F, size_t... I>
void CallWith(F f, const std::vector<double>& v, std::index_sequence<I...>)
{
  f(v[I]...);
}

/** The pass settings of vtkstylizeSettings.inc (generated from the classes). */
void AddPassSettings(OptionTable& t)
{
#define STYLIZE_NUMBER(Class, Setting, Type, Option, Metavar, Help)                                \
  t.Number<Class, Type>(Option, Metavar, Help, &Class::Get##Setting##MinValue,                     \
    &Class::Get##Setting##MaxValue, &Class::Get##Setting, &Class::Set##Setting);
#define STYLIZE_FLAG(Class, Setting, Value, Option, Help)                                          \
  t.Flag<Class>(Option, Help, &Class::Set##Setting, &Class::Get##Setting, Value);
#define STYLIZE_KEYWORDS(Class, Setting, Option, Metavar, Help, ...)                               \
  t.Keywords<Class>(                                                                               \
    Option, Metavar, Help, &Class::Get##Setting, &Class::Set##Setting, { __VA_ARGS__ });
#define STYLIZE_VECTOR(Class, Setting, Type, Count, Min, Max, Option, Metavar, Help)               \
  {                                                                                                \
    const Type* d = Defaults<Class>()->Get##Setting();                                             \
    std::string defaults;                                                                          \
    for (int i = 0; i < Count; ++i)                                                                \
    {                                                                                              \
      defaults += (i ? "," : "") + FormatNumber(d[i]);                                             \
    }                                                                                              \
    t.Vector<Class>(Option, Metavar, Help, Count, Min, Max, defaults,                              \
      [](Class* p, const std::vector<double>& v)                                                   \
      {                                                                                            \
        CallWith([p](auto... x) { p->Set##Setting(static_cast<Type>(x)...); }, v,                  \
          std::make_index_sequence<Count>());                                                      \
      });                                                                                          \
  }
#define STYLIZE_COLOR(Class, Setting, Option, Metavar, Help)                                       \
  t.Colour<Class>(Option, Metavar, Help, Defaults<Class>()->Get##Setting(), &Class::Set##Setting);
#include "vtkstylizeSettings.inc"
#undef STYLIZE_NUMBER
#undef STYLIZE_FLAG
#undef STYLIZE_KEYWORDS
#undef STYLIZE_VECTOR
#undef STYLIZE_COLOR
}

std::string StyleNames(const char* separator)
{
  std::string names;
  for (const StyleSpec& s : Styles())
  {
    names += (names.empty() ? "" : separator) + std::string(s.Name);
  }
  return names;
}

/** The program's own options and those a pass setting cannot express alone. */
// size: table
void AddProgramOptions(OptionTable& t)
{
  const Options o; // default values
  const char* general = "Output and scene";
  std::vector<std::string> styles;
  for (const StyleSpec& s : Styles())
  {
    styles.push_back(s.Name);
  }
  t.Value("--style", "NAME", "style: " + StyleNames("|") + " (default: " + o.Style + ")", general,
     [](Options& opt, const std::string& v) { opt.Style = v; })
    ->transform(OneOf(styles));
  t.Value("--output", "FILE",
     "output file: .png (image), .svg or .pdf (vector figure: outlines, dots, hatch lines, art "
     "pixels and text as vector shapes); with --orbit .png (numbered frames), .gif or .mp4 "
     "(default: " +
       o.Output + ")",
     general, [](Options& opt, const std::string& v) { opt.Output = v; })
    ->check(CLI::Validator(
      [](std::string& v) -> std::string
      {
        const std::string ext = v.size() >= 4 ? Lower(v.substr(v.size() - 4)) : std::string();
        const bool known =
          ext == ".png" || ext == ".svg" || ext == ".pdf" || ext == ".gif" || ext == ".mp4";
        return known ? std::string()
                     : "invalid value " + Quote(v) +
            ": the file name must end with .png, .svg, .pdf, .gif or .mp4";
      },
      ""));
  t.Value("--size", "WxH",
     "image size in pixels, W and H in [1, " + std::to_string(MaxImageSize) +
       "] (default: " + std::to_string(o.Width) + "x" + std::to_string(o.Height) + ")",
     general,
     [](Options& opt, const std::string& v)
     {
       const auto parts = Split(Lower(v), 'x');
       opt.Width = std::atoi(parts[0].c_str());
       opt.Height = std::atoi(parts[1].c_str());
     })
    ->check(CLI::Validator(
      [](std::string& v) -> std::string
      {
        const auto parts = Split(Lower(v), 'x');
        long w = 0, h = 0;
        if (parts.size() != 2 || !ParseInt(parts[0], w) || !ParseInt(parts[1], h) ||
          !std::isdigit(static_cast<unsigned char>(parts[0][0])) ||
          !std::isdigit(static_cast<unsigned char>(parts[1][0])))
        {
          return "invalid value " + Quote(v) + ": expected WxH, e.g. 1280x720";
        }
        if (w < 1 || w > MaxImageSize || h < 1 || h > MaxImageSize)
        {
          return v + " is out of range: width and height must be in [1, " +
            std::to_string(MaxImageSize) + "]";
        }
        return std::string();
      },
      ""));
  t.Value("--lights", "N",
     "number of scene lights in [0, " + std::to_string(MaxLights) +
       "]: 0 none, 1 the headlight, N > 1 white lights spread over a sphere around the scene, "
       "alternately directional and positional, each of intensity min(1, 3/N) (default: " +
       std::to_string(o.Lights) + ")",
     general, [](Options& opt, const std::string& v) { opt.Lights = std::atoi(v.c_str()); })
    ->check(NumberIn(0, MaxLights, true));
  t.Value("--azimuth", "DEG",
     "camera azimuth in degrees, about the view-up axis (default: " + FormatNumber(SceneAzimuth) +
       ", a three-quarter view)",
     general,
     [](Options& opt, const std::string& v) { opt.Azimuth = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(-MaxAngle, MaxAngle, false));
  t.Value("--elevation", "DEG",
     "camera elevation in degrees (default: " + FormatNumber(SceneElevation) +
       ", a three-quarter view)",
     general,
     [](Options& opt, const std::string& v) { opt.Elevation = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(-MaxAngle, MaxAngle, false));
  t.Value("--up", "+X|-X|+Y|-Y|+Z|-Z",
     "the data's up axis, drawn upward (as f3d's --up): a scan stored Z-up stands with +Z; the "
     "front view looks at the data from +X x up (+Z for the X axes), before --azimuth and "
     "--elevation (default: +Y)",
     general, [](Options& opt, const std::string& v) { opt.Up = v; })
    ->transform(OneOf({ "+x", "-x", "+y", "-y", "+z", "-z" }));
  t.Value("--orbit", "N",
     "an orbit animation: N frames, the camera turned by --orbit-degrees / N about the view-up "
     "axis between frames; writes FILE-0000.png ... and, with --output FILE.gif or FILE.mp4, the "
     "animation (ffmpeg); the patterns are anchored to the surface unless --anchor, "
     "--dither-anchor or --noise-space say otherwise (pixel art in texels; the sketch with "
     "--noise sparse unless --noise is given) (default: no orbit)",
     general, [](Options& opt, const std::string& v) { opt.Orbit = std::atoi(v.c_str()); })
    ->check(NumberIn(1, MaxOrbitFrames, true));
  t.Value("--orbit-degrees", "DEG",
     "the orbit's azimuth sweep in degrees, negative turns the other way (default: 360)", general,
     [](Options& opt, const std::string& v) { opt.OrbitDegrees = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(-3600, 3600, false));
  t.Value("--orbit-elevation", "DEG",
     "the orbit's elevation in degrees: the camera is raised by it before the orbit (default: 0)",
     general,
     [](Options& opt, const std::string& v)
     { opt.OrbitElevation = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(-89, 89, false));
  t.Value("--fps", "N", "frames per second of the .gif or .mp4 animation (default: 25)", general,
     [](Options& opt, const std::string& v) { opt.FramesPerSecond = std::atoi(v.c_str()); })
    ->check(NumberIn(1, 100, true));
  t.Value("--zoom", "F",
     "camera zoom factor, after the scene is fitted to fill " + FormatNumber(100 * FrameFill) +
       "% of the image's width or height (default: " + FormatNumber(o.Zoom) + ")",
     general,
     [](Options& opt, const std::string& v) { opt.Zoom = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(MinZoom, MaxZoom, false));
  t.Flag("--parallel", "parallel projection (default: perspective)", general,
    [](Options& opt, const std::string&) { opt.Parallel = true; });
  t.Value("--background", "R,G,B", "background colour, each component in [0, 1] (default: 1,1,1)",
     general,
     [](Options& opt, const std::string& v)
     {
       const auto c = ParseNumbers(v);
       std::copy(c.begin(), c.end(), opt.Background);
     })
    ->check(NumbersIn(3, 0.0, 1.0, "R,G,B"));
  t.Value("--magnify", "N",
     "write an image N times the window size, rendered in N x N tiles (vtkWindowToImageFilter "
     "scale) (default: 1)",
     general, [](Options& opt, const std::string& v) { opt.Magnify = std::atoi(v.c_str()); })
    ->check(NumberIn(1, MaxMagnify, true));
  t.Value("--time-step", "N",
     "time step to draw, an index from 0 into the file's time steps (Exodus, EnSight, "
     "OpenFOAM, .pvd) (default: 0, the first)",
     general,
     [](Options& opt, const std::string& v)
     {
       opt.TimeStep = std::atoi(v.c_str());
       opt.TimeStepGiven = true;
     })
    ->check(NumberIn(0, 1000000000, true));
  t.Value("--iso", "VALUE",
     "3D image data only: contour value, any finite number (default: Otsu's threshold of the "
     "point scalars, the value that best separates their two main populations: over a "
     "256-bin histogram, the split of largest between-class variance; printed as a note)",
     general,
     [](Options& opt, const std::string& v) { opt.IsoValue = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(-HUGE_VAL, HUGE_VAL, false));
  t.Value("--color-by", "ARRAY",
     "colour by this point (or cell) array (default: the active point scalars, if any)", general,
     [](Options& opt, const std::string& v) { opt.ColorBy = v; })
    ->check(CLI::Validator([](std::string& v)
      { return v.empty() ? std::string("expected an array name") : std::string(); },
      ""));
  t.Flag("--no-scalars", "ignore all arrays: one solid colour (default: off)", general,
    [](Options& opt, const std::string&) { opt.NoScalars = true; });
  t.Flag("--no-annotations", "no title and no scalar bar (default: both are drawn)", general,
    [](Options& opt, const std::string&) { opt.NoAnnotations = true; });
  t.Flag("--scalar-bar",
    "draw the colour legend on black-and-white output too (default: drawn where the style "
    "shows the data's colours: not for comic and sketch with --tint off, nor for lines)",
    general, [](Options& opt, const std::string&) { opt.ScalarBar = true; });
  t.Value("--multisamples", "N", "multisample anti-aliasing samples (default: 0)", general,
     [](Options& opt, const std::string& v) { opt.MultiSamples = std::atoi(v.c_str()); })
    ->check(NumberIn(0, MaxMultiSamples, true));
  t.Value("--memory-limit", "MIB",
     "the most memory reading and preparing the input may take, in MiB; an input that needs "
     "more is refused with one line (default: 3/4 of the machine's memory; 0: no limit; "
     "at least 64 otherwise)",
     general,
     [](Options& opt, const std::string& v) { opt.MemoryLimit = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(0, 1e9, false))
    ->check(CLI::Validator(
      [](std::string& v)
      {
        const double mib = std::strtod(v.c_str(), nullptr);
        return mib > 0.0 && mib < 64.0 ? std::string("at least 64 MiB, or 0 for no limit")
                                       : std::string();
      },
      ""));
  t.Value("--read-time-limit", "S",
     "the most processor time reading the input may take, in seconds (wall-clock: twice that "
     "and 5 s); a longer read is refused with one line (default: 0, automatic: 10 s + 1 s per "
     "MiB of input)",
     general,
     [](Options& opt, const std::string& v)
     { opt.ReadTimeLimit = std::strtod(v.c_str(), nullptr); })
    ->check(NumberIn(0, 1e6, false));
  t.Flag("--quiet", "do not print the output path on success (default: off)", general,
    [](Options& opt, const std::string&) { opt.Quiet = true; });
  t.Flag("--gbuffer", "render through the shared G-buffer pass (default: the lighting pass alone)",
    general, [](Options& opt, const std::string&) { opt.GBuffer = true; });

  // --lighting names the model as vtkStylizeLightingPass spells it.
  std::vector<std::string> models;
  for (int m = 0; m < 3; ++m)
  {
    models.push_back(Lower(vtkStylizeLightingPass::GetModelName(m)));
  }
  t.Value("--lighting", "MODEL",
     "lighting model: " + models[0] + "|" + models[1] + "|" + models[2] +
       " (default: the style's own: comic for comic, pixelart for pixel, standard otherwise)",
     "Lighting",
     [](Options& opt, const std::string& v)
     { opt.LightingModel = vtkStylizeLightingPass::GetModelFromName(v.c_str()); })
    ->transform(OneOf(models));

  // --palette: the palettes, and two shortcuts that also set the levels.
  using P = vtkPixelArtPass;
  const std::vector<std::pair<std::string, std::function<void(P*)>>> palettes = {
    { "levels", [](P* p) { p->SetPalette(P::LEVELS); } },
    { "grays", [](P* p) { p->SetPalette(P::GRAYS); } },
    { "1bit", [](P* p) { p->SetPaletteToOneBit(); } },
    { "4grays", [](P* p) { p->SetPaletteToFourGrays(); } },
    { "16", [](P* p) { p->SetPalette(P::PALETTE16); } },
    { "custom", [](P* p) { p->SetPalette(P::CUSTOM); } },
    { "colormap", [](P* p) { p->SetPalette(P::COLORMAP); } },
  };
  std::vector<std::string> paletteNames;
  for (const auto& p : palettes)
  {
    paletteNames.push_back(p.first);
  }
  t.Value("--palette", "levels|grays|1bit|4grays|16|custom|colormap",
     "pixel: levels per channel, grays, black and white, 4 grays, the 16-colour DawnBringer "
     "palette, the --colors list, or the data's colormap (default: levels)",
     GroupOf(static_cast<P*>(nullptr)).Group,
     [palettes](Options& opt, const std::string& v)
     {
       for (const auto& p : palettes)
       {
         if (p.first == v)
         {
           opt.Passes.Of<P>().push_back(p.second);
         }
       }
     })
    ->transform(OneOf(paletteNames));
  t.Value("--colors", "LIST",
     "pixel: the custom palette: colours (R,G,B or #rrggbb) separated by spaces or ';', at most "
     "256; selects --palette custom",
     GroupOf(static_cast<P*>(nullptr)).Group,
     [](Options& opt, const std::string& v)
     {
       std::string error;
       const auto colours = ParseColorList(v, error);
       opt.Passes.Of<P>().push_back(
         [colours](P* p)
         {
           p->RemoveAllPaletteColors();
           for (const auto& c : colours)
           {
             p->AddPaletteColor(c[0], c[1], c[2]);
           }
           p->SetPalette(P::CUSTOM);
         });
     })
    ->check(CLI::Validator(
      [](std::string& v)
      {
        std::string error;
        ParseColorList(v, error);
        return error;
      },
      ""));
}

/** What some generated options also do beyond setting their pass. */
void AddOptionEffects(OptionTable& t)
{
  // The program computes the principal directions only when the pass uses them.
  t.Also("--direction-source",
    [](Options& opt, const std::string& v) { opt.ModelDirections = v == "model"; });
}

/** Wraps help text at the terminal's usual width, for CLI11's indented description column. */
class Formatter : public CLI::Formatter
{
public:
  Formatter() { this->column_width(30); }
  std::string make_option_desc(const CLI::Option* opt) const override
  {
    std::istringstream words(CLI::Formatter::make_option_desc(opt));
    std::string word, line, out;
    const size_t width = 79 - 30;
    while (words >> word)
    {
      if (!line.empty() && line.size() + 1 + word.size() > width)
      {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
  }
};

const char* Description =
  "Renders INPUT, or the built-in scene when no INPUT is given, offscreen through the VTK\n"
  "Stylize render passes and writes a PNG image.\n"
  "\n"
  "INPUT formats, chosen by extension (case-insensitive):\n"
  "  .vtp .vtu .vts .vtr .vti .vtm  VTK XML files\n"
  "  .pvtp .pvtu .pvts .pvtr .pvti  VTK parallel XML files\n"
  "  .pvd                           ParaView data collections (see --time-step)\n"
  "  .vtk                           VTK legacy files\n"
  "  .ex2 .exo .e .g                Exodus II (every element block)\n"
  "  .case                          EnSight\n"
  "  .foam                          OpenFOAM cases\n"
  "  .stl .obj .ply                 surface meshes\n"
  "Volumes and grids are drawn as their outer surface; image data with a point scalar array\n"
  "is drawn as a contour (see --iso); each block of a multiblock file is drawn as its own\n"
  "actor. Surfaces are coloured by their active point (else cell) scalars through a colour\n"
  "map unless --color-by or --no-scalars says otherwise. Options: --opt VALUE or --opt=VALUE;\n"
  "a later option overrides an earlier one.";

const char* Footer =
  "On success the output path is printed on stdout, and on stderr lines starting with\n"
  "\"vtkstylize: warning: \" (an option that does not apply) or \"vtkstylize: note: \" (a\n"
  "value the program chose, e.g. the contour value); --quiet leaves out the path and the\n"
  "notes. On failure one line starting with \"vtkstylize: \" is printed on stderr (and\n"
  "nothing else) and no output file is written.\n"
  "On a terminal, a step that takes more than a second (normals, curvatures, finding the\n"
  "lines of a large mesh) shows a progress bar on stderr, cleared when it ends (not with\n"
  "--quiet). An interrupt (Ctrl-C) stops the run: one line, no output file.\n"
  "Exit status: 0 success, 1 input, rendering or output error, 2 usage error (unknown\n"
  "option, bad option value, unsupported INPUT extension).\n"
  "Environment: VTKSTYLIZE_VERBOSE=1 also shows VTK's own messages on stderr.\n"
  "OpenGL needs an X display, even offscreen: without DISPLAY, vtkstylize starts Xvfb on a\n"
  "free display for the run (package xvfb).\n"
  "The input is read in a child process under limits (memory: --memory-limit, else 512 MiB\n"
  "+ 16 x the input; time: --read-time-limit): a reader that crashes or runs away is one line.";

/** The application with every option; `input` receives the positional arguments. */
struct CommandLine
{
  CLI::App App{ Description, "vtkstylize" };
  OptionTable Table{ App };
  std::vector<std::string> Inputs;
  CLI::Option* Help = nullptr;
  CLI::Option* Version = nullptr;

  CommandLine()
  {
    this->App.formatter(std::make_shared<Formatter>());
    this->App.footer(Footer);
    this->App.set_help_flag(); // --help is ours: it must win over every other error
    this->Help = this->App.add_flag("--help", "print this help and exit")->disable_flag_override();
    this->Version =
      this->App.add_flag("--version", "print the version and exit")->disable_flag_override();
    this->App.add_option("INPUT", this->Inputs, "the data file (default: the built-in scene)");
    AddProgramOptions(this->Table);
    AddPassSettings(this->Table);
    AddOptionEffects(this->Table);
  }
};
}

namespace
{
/** A style pass with the lighting pass's model and the settings given for its classes. */
template <class Pass>
vtkSmartPointer<Pass> MakeStyle(vtkStylizeLightingPass* lighting, const Options& opt)
{
  auto pass = vtkSmartPointer<Pass>::New();
  pass->GetLightingPass()->SetModel(lighting->GetModel());
  opt.Passes.ApplyTo(pass->GetLightingPass());
  opt.Passes.template ApplyTo<Pass>(pass);
  return pass;
}
}

//------------------------------------------------------------------------------
const std::vector<StyleSpec>& Styles()
{
  // Each style's pass gets the lighting pass's model, then the settings given for its classes.
  static const std::vector<StyleSpec> styles = {
    { "none", "no style pass: the lighting model only", -1,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass* gbuffer,
        const Options&) -> vtkSmartPointer<vtkRenderPass>
      {
        if (gbuffer)
        {
          return gbuffer;
        }
        return lighting;
      } },
    { "comic", "black-and-white comic: edges, halftone dots, hatching (vtkComicPass)",
      vtkStylizeLightingPass::COMIC,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const Options& opt) -> vtkSmartPointer<vtkRenderPass>
      { return MakeStyle<vtkComicPass>(lighting, opt); } },
    { "pixel",
      "pixel art: pixelation, Canny outlines, 8x8 ordered dither to a palette (vtkPixelArtPass)",
      vtkStylizeLightingPass::PIXEL_ART,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const Options& opt) -> vtkSmartPointer<vtkRenderPass>
      { return MakeStyle<vtkPixelArtPass>(lighting, opt); } },
    { "sketch",
      "pencil sketch: principal-direction strokes (line integral convolution of solid noise), "
      "pencil tone (vtkSketchPass)",
      vtkStylizeLightingPass::STANDARD,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const Options& opt) -> vtkSmartPointer<vtkRenderPass>
      { return MakeStyle<vtkSketchPass>(lighting, opt); } },
    { "lines",
      "line art: contours, creases, ridges, valleys and suggestive contours found on the mesh, "
      "hidden lines removed, in ink on paper (vtkLineArtPass)",
      vtkStylizeLightingPass::STANDARD,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const Options& opt) -> vtkSmartPointer<vtkRenderPass>
      { return MakeStyle<vtkLineArtPass>(lighting, opt); } },
  };
  return styles;
}

//------------------------------------------------------------------------------
const StyleSpec* FindStyle(const std::string& name)
{
  for (const StyleSpec& s : Styles())
  {
    if (name == s.Name)
    {
      return &s;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::string HelpText()
{
  CommandLine cl;
  return cl.App.help();
}

//------------------------------------------------------------------------------
Options ParseCommandLine(int argc, char* argv[])
{
  CommandLine cl;
  Options opt;
  try
  {
    cl.App.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    // --help and --version win over the other options' errors, as they do when parsing succeeds.
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--")
      {
        break;
      }
      opt.Help = opt.Help || arg == "--help";
      opt.Version = opt.Version || arg == "--version";
    }
    if (opt.Help || opt.Version)
    {
      return opt;
    }
    UsageError(e.what());
  }
  opt.Help = cl.Help->count() > 0;
  opt.Version = cl.Version->count() > 0;
  if (opt.Help || opt.Version)
  {
    return opt;
  }
  cl.Table.Apply(opt);
  opt.AnchorGiven =
    cl.App.count("--anchor") + cl.App.count("--dither-anchor") + cl.App.count("--noise-space") > 0;
  opt.NoiseGiven = cl.App.count("--noise") > 0;
  {
    const std::string ext = Lower(opt.Output.substr(opt.Output.size() - 4));
    if (opt.Orbit > 0 && (ext == ".svg" || ext == ".pdf"))
    {
      UsageError("--orbit writes .png frames, a .gif or an .mp4, not " + Quote(opt.Output));
    }
    if (opt.Orbit == 0 && (ext == ".gif" || ext == ".mp4"))
    {
      UsageError("--output " + Quote(opt.Output) + " is an animation: give --orbit N");
    }
    if ((ext == ".svg" || ext == ".pdf") && opt.Style == "none")
    {
      // known before anything is read or rendered
      UsageError("a vector figure (" + Quote(opt.Output) +
        ") draws a style's layers: give --style comic, pixel, sketch or lines, not none");
    }
  }
  const std::vector<std::string>& positional = cl.Inputs;
  if (positional.size() > 1)
  {
    UsageError("too many arguments: expected at most one INPUT file, got " +
      std::to_string(positional.size()) + " (" + Quote(positional[0]) + ", " +
      Quote(positional[1]) + (positional.size() > 2 ? ", ..." : "") + ")");
  }
  if (!positional.empty())
  {
    opt.Input = positional[0];
    if (opt.Input.empty())
    {
      UsageError("the INPUT file name is empty");
    }
  }
  return opt;
}
}
