#!/usr/bin/python3
"""bench_nsga2_deap.py: DEAP's NSGA-II on ZDT1, the baseline of bench_nsga2.

    /usr/bin/python3 tests/bench/bench_nsga2_deap.py [RUNS]

Debian's python3-deap, with the settings of Facet's bench_nsga2: ZDT1 with
30 variables in [0, 1], population 100, 250 generations (the initial one
included: 25,000 evaluations), every child evaluated; mating by
tools.selTournamentDCD, tools.cxSimulatedBinaryBounded (eta 20) with
probability 0.9 per pair, tools.mutPolynomialBounded (eta 20, 1/30 per
variable) on every child, survival by tools.selNSGA2. Runs RUNS times
(default 1) with seeds 1..RUNS and prints a line per run and

    deap: evaluations/s E (best of RUNS) hypervolume H (mean of RUNS)

with H the hypervolume of the final population w.r.t. (1.1, 1.1).
"""
import array
import random
import sys
import time

from deap import base, benchmarks, creator, tools

NVARS = 30
POPULATION = 100
GENERATIONS = 250
CROSSOVER = 0.9
ETA = 20.0


def hypervolume_2d(points, reference=(1.1, 1.1)):
    """Area dominated by points and bounded by reference (minimising)."""
    inside = sorted(p for p in points
                    if p[0] < reference[0] and p[1] < reference[1])
    area, lowest = 0.0, reference[1]
    for x, y in inside:
        if y < lowest:
            area += (reference[0] - x) * (lowest - y)
            lowest = y
    return area


def make_toolbox(counter):
    creator.create("FitnessMin", base.Fitness, weights=(-1.0, -1.0))
    creator.create("Individual", array.array, typecode="d",
                   fitness=creator.FitnessMin)
    toolbox = base.Toolbox()
    toolbox.register("attr", random.uniform, 0.0, 1.0)
    toolbox.register("individual", tools.initRepeat, creator.Individual,
                     toolbox.attr, NVARS)
    toolbox.register("population", tools.initRepeat, list,
                     toolbox.individual)

    def evaluate(individual):
        counter[0] += 1
        return benchmarks.zdt1(individual)

    toolbox.register("evaluate", evaluate)
    toolbox.register("mate", tools.cxSimulatedBinaryBounded, low=0.0,
                     up=1.0, eta=ETA)
    toolbox.register("mutate", tools.mutPolynomialBounded, low=0.0, up=1.0,
                     eta=ETA, indpb=1.0 / NVARS)
    toolbox.register("select", tools.selNSGA2)
    return toolbox


def run(toolbox, seed):
    random.seed(seed)
    population = toolbox.population(n=POPULATION)
    for individual in population:
        individual.fitness.values = toolbox.evaluate(individual)
    # selNSGA2 on the whole population only assigns crowding distances.
    population = toolbox.select(population, len(population))
    for _ in range(1, GENERATIONS):
        parents = tools.selTournamentDCD(population, len(population))
        children = [toolbox.clone(p) for p in parents]
        for a, b in zip(children[::2], children[1::2]):
            if random.random() <= CROSSOVER:
                toolbox.mate(a, b)
            toolbox.mutate(a)
            toolbox.mutate(b)
            del a.fitness.values, b.fitness.values
        for child in children:
            child.fitness.values = toolbox.evaluate(child)
        population = toolbox.select(population + children, POPULATION)
    return population


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    counter = [0]
    toolbox = make_toolbox(counter)
    best_rate, volumes = 0.0, []
    for seed in range(1, runs + 1):
        counter[0] = 0
        start = time.perf_counter()
        population = run(toolbox, seed)
        seconds = time.perf_counter() - start
        volume = hypervolume_2d([ind.fitness.values for ind in population])
        rate = counter[0] / seconds
        print("deap run %d: %d evaluations in %.3f s, %.0f/s, "
              "hypervolume %.6f" % (seed, counter[0], seconds, rate, volume))
        best_rate = max(best_rate, rate)
        volumes.append(volume)
    print("deap: evaluations/s %.0f (best of %d) hypervolume %.6f "
          "(mean of %d, ZDT1, reference 1.1,1.1)"
          % (best_rate, runs, sum(volumes) / runs, runs))


if __name__ == "__main__":
    main()
