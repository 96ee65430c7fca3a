// `impetus calc` entries for sound (ch. 26): waves and beats, the speed of sound against
// temperature, levels and the inverse-square law, OpenAL's distance models, echoes and
// reflections, the Doppler shift (and a passing source), interaural time and level differences.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/audio/audio.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <cmath>
#include <string>

namespace impetus::cli {
namespace {

using namespace impetus::audio;

constexpr const char* topic = "sound (ch. 26)";

Param speedOfSoundParam() {
  return {"speed-of-sound", "m/s", "c (OpenAL's default, air at 20 C)", std::string("343.3")};
}

Result wave(const Args& a) {
  const HarmonicWave w{a.number("amplitude"), a.number("frequency"), 0.0, a.number("speed-of-sound")};
  requireValid(w);
  Result r;
  r.add("wavelength", w.wavelength(), "m", "lambda = c / f");
  r.add("period", w.period(), "s", "T = 1 / f");
  r.add("angular_frequency", w.angularFrequency(), "rad/s", "w = 2 pi f");
  r.add("wavenumber", w.wavenumber(), "rad/m", "k = 2 pi / lambda");
  r.add("pressure", w.pressure(requireFinite(a.number("x"), "x"), requireFinite(a.number("time"), "time")), "Pa",
        "A sin(k x - w t)");
  r.notes.emplace_back("the book writes f = 1/lambda; f = c/lambda (and f = 1/T)");
  return r;
}

Result beats(const Args& a) {
  const double f1 = a.number("frequency1");
  const double f2 = a.number("frequency2");
  Result r;
  r.add("beat_frequency", beatFrequency(f1, f2), "Hz", "|f1 - f2|: loudness swells this often");
  r.add("tone", 0.5 * (f1 + f2), "Hz", "the pitch heard, (f1 + f2)/2");
  r.add("beat_period", 1.0 / beatFrequency(f1, f2), "s");
  return r;
}

Result speedOfSound(const Args& a) {
  const double c = speedOfSoundInAir(a.number("temperature"));
  Result r;
  r.add("speed_of_sound", c, "m/s", "331.3 sqrt(1 + T/273.15)");
  r.add("wavelength_440", wavelength(440.0, c), "m", "of concert A");
  return r;
}

Result soundLevel(const Args& a) {
  const double power = a.number("power");
  const double distance = a.number("distance");
  const double impedance = a.number("impedance");
  requirePositive(impedance, "impedance");
  const double intensity = intensityAtDistance(power, distance);
  Result r;
  r.add("intensity", intensity, "W/m^2", "P / (4 pi r^2)");
  r.add("intensity_level", intensityLevel(intensity), "dB", "10 log10(I / 1e-12 W/m^2)");
  const double p = std::sqrt(intensity * impedance);
  r.add("pressure_rms", p, "Pa", "sqrt(I rho c)");
  r.add("pressure_level", pressureLevel(p), "dB", "20 log10(p / 20 uPa)");
  return r;
}

Result attenuation(const Args& a) {
  const double level = a.number("level");
  const double r1 = a.number("distance1");
  const double r2 = a.number("distance2");
  Result r;
  r.add("level", levelAtDistance(level, r1, r2), "dB", "L - 20 log10(r2 / r1)");
  r.add("amplitude_ratio", amplitudeRatio(r1, r2), "", "pressure amplitude ~ 1/r");
  r.add("intensity_ratio", intensityRatio(r1, r2), "", "intensity ~ 1/r^2");
  r.add("loudness_ratio", loudnessRatio(levelAtDistance(level, r1, r2) - level), "",
        "perceived, 2^(dL/10): twice as loud per +10 dB");
  r.notes.emplace_back(
      "the book has the amplitude falling as 1/r^2: that is the intensity; the amplitude falls as 1/r");
  return r;
}

DistanceModel distanceModel(const std::string& name) {
  if (name == "none") {
    return DistanceModel::none;
  }
  if (name == "inverse") {
    return DistanceModel::inverse;
  }
  if (name == "inverse-clamped") {
    return DistanceModel::inverseClamped;
  }
  if (name == "linear") {
    return DistanceModel::linear;
  }
  if (name == "linear-clamped") {
    return DistanceModel::linearClamped;
  }
  if (name == "exponent") {
    return DistanceModel::exponent;
  }
  if (name == "exponent-clamped") {
    return DistanceModel::exponentClamped;
  }
  throw Error("distanceModel", "--distance-model = '" + name +
                                   "': must be none, inverse, inverse-clamped, linear, linear-clamped, exponent or "
                                   "exponent-clamped");
}

Result distanceGainModel(const Args& a) {
  const DistanceAttenuation att{distanceModel(a.text("distance-model")), a.number("reference-distance"),
                                a.number("max-distance"), a.number("rolloff")};
  const double g = distanceGain(att, a.number("distance"));
  Result r;
  r.add("gain", g, "", "amplitude gain OpenAL applies");
  if (g > 0.0) {
    r.add("gain_db", 20.0 * std::log10(g), "dB");
  }
  return r;
}

Result echo(const Args& a) {
  const double d = a.number("distance");
  const double c = a.number("speed-of-sound");
  Result r;
  r.add("echo_delay", echoDelay(d, c), "s", "2 d / c: there and back");
  r.add("flash_to_bang", flashToBangDelay(d, c), "s", "d/c - d/c_light: an event d away seen, then heard");
  return r;
}

Result reflection(const Args& a) {
  const PlaneReflection p =
      reflectOffPlane(vector3(a, "source"), vector3(a, "listener"), vector3(a, "plane-point"),
                      vector3(a, "plane-normal"), a.number("coefficient"), a.number("speed-of-sound"));
  Result r;
  r.add("image_source", toVector(p.imageSource), "m", "the source mirrored in the plane");
  r.add("reflection_point", toVector(p.reflectionPoint), "m");
  r.add("direct_path", p.directPath, "m");
  r.add("reflected_path", p.reflectedPath, "m");
  r.add("lag", p.lag, "s", "reflection after the direct sound");
  r.add("amplitude_ratio", p.amplitudeRatio, "", "R direct / reflected path");
  r.add("level_difference", p.levelDifference, "dB");
  return r;
}

Result doppler(const Args& a) {
  const double f = a.number("frequency");
  const double vs = a.number("source-speed");
  const double vl = a.number("listener-speed");
  const double c = a.number("speed-of-sound");
  const double heard = dopplerFrequency(f, vs, vl, c);
  Result r;
  r.add("frequency", heard, "Hz", "f (c + v_L) / (c - v_S)");
  r.add("shift", heard - f, "Hz");
  r.add("ratio", heard / f, "", "pitch factor");
  r.add("semitones", 12.0 * std::log2(heard / f), "");
  return r;
}

Result dopplerPass(const Args& a) {
  const PassBy pass{a.number("frequency"), a.number("speed"), a.number("closest-approach"), 0.0,
                    a.number("speed-of-sound")};
  const double t = a.number("time");
  const double c = pass.speedOfSound;
  Result r;
  r.add("heard_frequency", passByHeardFrequency(pass, t), "Hz",
        "f c / (c - v cos theta), theta at emission (retarded time)");
  r.add("openal_frequency", passByInstantaneousFrequency(pass, t), "Hz", "from the positions now, as OpenAL computes");
  r.add("emission_time", passByEmissionTime(pass, t), "s", "when the sound heard at --time left the source");
  r.add("approaching_frequency", dopplerFrequency(pass.frequency, pass.speed, 0.0, c), "Hz", "far before: f c/(c - v)");
  r.add("receding_frequency", dopplerFrequency(pass.frequency, -pass.speed, 0.0, c), "Hz", "far after: f c/(c + v)");
  return r;
}

Result interaural(const Args& a) {
  const double azimuth = degToRad(a.number("azimuth"));
  const double f = a.number("frequency");
  const double c = a.number("speed-of-sound");
  Result r;
  r.add("itd", interauralTimeDifference(azimuth, a.number("ear-spacing"), c), "s", "(d / c) sin(azimuth)");
  r.add("itd_woodworth", woodworthTimeDifference(azimuth, a.number("head-radius"), c), "s",
        "(a / c)(theta + sin theta), round a spherical head");
  r.add("ild", interauralLevelDifference(azimuth, f, a.number("head-radius"), c), "dB",
        "head shadow (Brown-Duda), + right ear louder");
  return r;
}

} // namespace

void registerAudioModels(Registry& registry) {
  registry.add({"sound-wave",
                topic,
                "harmonic sound wave: wavelength c/f, period, wavenumber, pressure A sin(k x - w t)",
                {{"frequency", "Hz", "f", std::string("440")},
                 {"amplitude", "Pa", "pressure amplitude A", std::string("1")},
                 {"x", "m", "position along the wave", std::string("0")},
                 {"time", "s", "time", std::string("0")},
                 speedOfSoundParam()},
                wave});
  registry.add({"beats",
                topic,
                "superposition of two close tones: beat frequency |f1 - f2|",
                {{"frequency1", "Hz", "first tone", std::string("440")},
                 {"frequency2", "Hz", "second tone", std::string("444")}},
                beats});
  registry.add({"speed-of-sound",
                topic,
                "speed of sound in dry air against temperature: 331.3 sqrt(1 + T/273.15)",
                {{"temperature", "degC", "air temperature", std::string("20")}},
                speedOfSound});
  registry.add({"sound-level",
                topic,
                "a point source's intensity P/(4 pi r^2) and level in dB at a distance",
                {{"power", "W", "acoustic power radiated", std::string("1")},
                 {"distance", "m", "distance from the source", std::string("1")},
                 {"impedance", "Pa s/m", "rho c of the air (413 at 20 C)", std::string("413.3")}},
                soundLevel});
  registry.add({"sound-attenuation",
                topic,
                "inverse-square law: level at r2 from the level at r1 (amplitude 1/r, intensity 1/r^2)",
                {{"level", "dB", "level at distance1", std::string("100")},
                 {"distance1", "m", "where the level is known", std::string("1")},
                 {"distance2", "m", "where it is wanted", std::string("2")}},
                attenuation});
  registry.add({"distance-gain",
                topic,
                "OpenAL's distance models: the gain a source gets at a distance",
                {{"distance-model", "", "none, inverse, inverse-clamped, linear(-clamped), exponent(-clamped)",
                  std::string("inverse-clamped"), ParamKind::text},
                 {"distance", "m", "source to listener", std::nullopt},
                 {"reference-distance", "m", "where the gain is 1", std::string("1")},
                 {"max-distance", "m", "where attenuation stops (clamped models)", std::string("1e30")},
                 {"rolloff", "", "rolloff factor", std::string("1")}},
                distanceGainModel});
  registry.add({"echo",
                topic,
                "echo delay from a reflector 2d/c, and the flash-to-bang delay of an event d away",
                {{"distance", "m", "to the reflector or event", std::nullopt}, speedOfSoundParam()},
                echo});
  registry.add({"reflection",
                topic,
                "a reflection off a plane wall by the image source: paths, lag, amplitude",
                {vectorParam("source", "m", "source position", std::nullopt),
                 vectorParam("listener", "m", "listener position", std::nullopt),
                 vectorParam("plane-point", "m", "a point of the wall", std::string("0,0,0")),
                 vectorParam("plane-normal", "", "the wall's normal", std::string("0,1,0")),
                 {"coefficient", "", "pressure reflection coefficient 0..1", std::string("1")},
                 speedOfSoundParam()},
                reflection});
  registry.add({"doppler",
                topic,
                "Doppler shift f (c + v_L)/(c - v_S) for a moving source and listener",
                {{"frequency", "Hz", "emitted frequency", std::string("440")},
                 {"source-speed", "m/s", "source's speed toward the listener (negative: away)", std::string("0")},
                 {"listener-speed", "m/s", "listener's speed toward the source (negative: away)", std::string("0")},
                 speedOfSoundParam()},
                doppler});
  registry.add({"doppler-pass",
                topic,
                "a source passing a still listener in a straight line: the frequency heard at a time",
                {{"frequency", "Hz", "emitted frequency", std::string("440")},
                 {"speed", "m/s", "source speed (below c)", std::string("30")},
                 {"closest-approach", "m", "distance at the closest point", std::string("10")},
                 {"time", "s", "time since the closest point (negative: before)", std::string("-5")},
                 speedOfSoundParam()},
                dopplerPass});
  registry.add({"interaural",
                topic,
                "interaural time (free field, Woodworth) and level (head shadow) differences",
                {{"azimuth", "deg", "source direction from straight ahead, + right", std::string("90")},
                 {"frequency", "Hz", "for the level difference", std::string("2000")},
                 {"ear-spacing", "m", "free-field ear spacing", std::string("0.17")},
                 {"head-radius", "m", "spherical head radius", std::string("0.0875")},
                 speedOfSoundParam()},
                interaural});
}

} // namespace impetus::cli
