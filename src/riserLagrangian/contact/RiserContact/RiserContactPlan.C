/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    RiserContact, part 2 of 3: the plan of a step's sub-cycles: which particles can reach the wall or
    each other within the step, their clusters (the core's ClusterPlan) and
    needs, across processors (prepareSubCycles) (RiserContact.H, Description).

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalarField Foam::RiserContact<CloudType>::cellAxisDistances
(
    const polyMesh& mesh
)
{
    const pointField& points = mesh.points();
    const faceList& faces = mesh.faces();
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    auto axisDistance = [](const point& x)
    {
        return Foam::sqrt(sqr(x.x()) + sqr(x.y()));
    };

    // the centre, then the points of each face of the cell
    scalarField h(mesh.nCells());
    forAll(h, celli)
    {
        h[celli] = axisDistance(mesh.cellCentres()[celli]);
    }
    forAll(faces, facei)
    {
        scalar hf = 0;
        for (const label pointi : faces[facei])
        {
            hf = max(hf, axisDistance(points[pointi]));
        }
        h[owner[facei]] = max(h[owner[facei]], hf);
        if (facei < mesh.nInternalFaces())
        {
            h[neighbour[facei]] = max(h[neighbour[facei]], hf);
        }
    }
    return h;
}


template<class CloudType>
void Foam::RiserContact<CloudType>::checkMeshUnchanged() const
{
    const polyMesh& mesh = this->owner().mesh();
    if (mesh.changing() || cellAxisDistance_.size() != mesh.nCells())
    {
        cellAxisDistance_.clear();
    }
}


template<class CloudType>
bool Foam::RiserContact<CloudType>::clearOfWall
(
    const parcelType& p,
    const scalar axisOffset,
    const scalar reach
) const
{
    // the particle's distance from the axis is at most its cell's from the
    // z axis plus the axis' offset; the tolerance is far beyond the
    // round-off of the particle's coordinates in its tetrahedron
    const riser::RiserFlow& flow = riser_.flow();
    return
        cellAxisDistance_.size()
     && flow.radius() - (cellAxisDistance_[p.cell()] + axisOffset) - 0.5*p.d()
      > reach + 1e-6*flow.diameter();
}



template<class CloudType>
Foam::label Foam::RiserContact<CloudType>::nearWallSubCycles
(
    const parcelType& p,
    const scalar axisOffset
) const
{
    const Time& time = this->owner().mesh().time();
    const riser::RiserFlow& flow = riser_.flow();
    const riser::Wall& wall = riser_.wall();
    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;

    if (!(p.d() < flow.diameter()))
    {
        FatalErrorInFunction
            << "particle " << p.origId() << " of diameter " << p.d()
            << " is not smaller than the riser diameter D = "
            << flow.diameter() << " (constant/riserProperties)"
            << exit(FatalError);
    }
    if (!wallLaw_.valid())
    {
        return 0;
    }
    // the particle's speed toward the wall now, at most, and what the body
    // forces can add over the step: a particle at rest beside the wall
    // reaches it in a step by its acceleration alone
    const scalar speed0 = mag(p.U()) + flow.motion().maxSpeed();
    const scalar aBody = bodyAccelerationBound();
    // lubricated: a particle that may be in the wall's film within the
    // step is sub-cycled as one that may touch, so that its step changes
    // where the film is weak (at its cut-off), not near touch, where a
    // changed step would cost part of an evaluation's impulse
    // (riserCore's contactKernel.hpp)
    const scalar reach =
        speed0*dt + 0.5*aBody*sqr(dt) + wallFilmGap(0.5*p.d());
    if (clearOfWall(p, axisOffset, reach))
    {
        return 0;
    }
    const scalar gap = wall.distance(toCore(p.position()), t0) - 0.5*p.d();
    if (p.age() == 0 && gap <= 0)
    {
        // injected in this step (a parcel that moved between processors
        // is older): released touching or overlapping the wall
        FatalErrorInFunction
            << "particle " << p.origId() << " (processor " << p.origProc()
            << ") of diameter " << p.d() << " is released at "
            << p.position() << " at t = " << t0 << " touching or"
            << " overlapping the riser wall: overlap " << -gap
            << " >= 0; release it at least d/2 from the wall"
            << exit(FatalError);
    }
    if (gap > reach)
    {
        return 0;
    }
    // at the largest impact speed within the step: over the distance s it
    // can close toward the wall, the body forces raise the speed of
    // approach v to at most sqrt(v0^2 + 2 a_b s)
    const scalar closing = min(max(gap, scalar(0)), speed0*dt + 0.5*aBody*sqr(dt));
    const scalar impactSpeed = sqrt(sqr(speed0) + 2*aBody*closing);
    const riser::ContactBody body(0.5*p.d(), effectiveMass(p));
    const scalar tc = wallLaw_->contactTime(body, max(impactSpeed, SMALL));
    // as a scalar first: no overflow of the label
    const scalar needed = ceil(stepsPerContact_*dt/tc);
    checkNeeded
    (
        needed, labelPair(p.origProc(), p.origId()), p.position(), tc,
        "wall contact"
    );
    return max(label(needed), label(1));
}


template<class CloudType>
void Foam::RiserContact<CloudType>::checkNeeded
(
    const scalar needed,
    const labelPair& key,
    const vector& position,
    const scalar tc,
    const string& what
) const
{
    if (!(needed <= maxSubCycles_))
    {
        FatalErrorInFunction
            << "particle " << key.second() << " (processor " << key.first()
            << ") at " << position << " needs " << needed
            << " sub-cycles of the step deltaT = "
            << this->owner().mesh().time().deltaTValue() << " to resolve"
            << " its " << what.c_str() << " (contact time " << tc << " s, "
            << stepsPerContact_ << " sub-cycles each), more than"
            << " maxSubCycles = " << maxSubCycles_ << ": reduce deltaT or"
            << " raise maxSubCycles" << exit(FatalError);
    }
}


template<class CloudType>
template<class PairFunction>
void Foam::RiserContact<CloudType>::forEachNearPair
(
    const std::vector<riser::Vector>& x,
    const scalar cutoff,
    const PairFunction& f
) const
{
    riser::NearPairs pairs;
    if (riser_.section().periodic)
    {
        pairs.setPeriodic(riser_.section().z0, riser_.section().length);
    }
    pairs.forEachPair(x, cutoff, f);
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::pairGap
(
    const riser::Vector& xa,
    const labelPair& ka,
    const scalar Ra,
    const riser::Vector& xb,
    const labelPair& kb,
    const scalar Rb
) const
{
    return
        riser::nearestImage
        (
            ka < kb ? riser::Vector(xb - xa) : riser::Vector(xa - xb),
            riser_.section().period()
        ).norm()
      - (Ra + Rb);
}


template<class CloudType>
void Foam::RiserContact<CloudType>::prepareSubCycles() const
{
    checkCloudRunsThis();
    const Time& time = this->owner().mesh().time();
    const scalar dt = time.deltaTValue();
    preparedIndex_ = time.timeIndex();
    checkMeshUnchanged();
    const scalar axisOffset =
        riser_.flow().motion().axisOffsetBound(time.value() - dt);

    // this processor's particles: key, wall need
    const label nOwn = this->owner().size();
    List<labelPair> ownKeys(nOwn);
    labelList ownNeed(nOwn);
    {
        label i = 0;
        for (const parcelType& p : this->owner())
        {
            ownKeys[i] = labelPair(p.origProc(), p.origId());
            ownNeed[i] = nearWallSubCycles(p, axisOffset);
            ++i;
        }
    }
    needs_.clear();
    if (!pairLaw_.valid())
    {
        forAll(ownKeys, i)
        {
            needs_.set
            (
                ownKeys[i],
                subCycleNeed{ownNeed[i], aloneMeshFree_ && ownNeed[i] > 0}
            );
        }
        return;
    }

    // with pairs: the clusters. Each processor finds the pairs of its own
    // particles, with copies of the other processors' particles near its
    // own (ghosts: nearProcessors), and the clusters' needs (each
    // cluster's largest) spread across the processors by exchanging the
    // needs of the particles each holds as another's ghosts until none
    // grows
    List<vector> ownX(nOwn);
    // per particle: position (3), key (2), U (3), d, m_eff, need,
    // injected now (sent to the other processors as one row of numbers)
    const label nData = 12;
    List<scalar> ownData(nData*nOwn);
    scalar rMax = 0, uMax = 0;
    {
        label i = 0;
        for (const parcelType& p : this->owner())
        {
            ownX[i] = p.position();
            scalar* d = &ownData[nData*i];
            d[0] = ownX[i].x();
            d[1] = ownX[i].y();
            d[2] = ownX[i].z();
            d[3] = p.origProc();
            d[4] = p.origId();
            d[5] = p.U().x();
            d[6] = p.U().y();
            d[7] = p.U().z();
            d[8] = p.d();
            d[9] = effectiveMass(p);
            d[10] = ownNeed[i];
            // injected in this step (a parcel that moved between
            // processors is older)
            d[11] = p.age() == 0;
            rMax = max(rMax, 0.5*p.d());
            uMax = max(uMax, mag(p.U()));
            ++i;
        }
    }
    reduce(rMax, maxOp<scalar>());
    reduce(uMax, maxOp<scalar>());
    // within a step a contact can speed a particle up to about twice the
    // fastest particle's speed, so a pair may close by 4 U_max dt: a reach
    // from each pair's own speeds would miss a resting particle struck by
    // a neighbour and left to overlap the next; and the body forces can
    // change two particles' relative velocity by up to 2 a_b dt over the
    // step, their gap by a_b dt^2 (particles at rest released side by
    // side settle at different speeds)
    const scalar pairSpeedGain = 2*bodyAccelerationBound()*dt;
    reach_ = (4*uMax + 0.5*pairSpeedGain)*dt;
    radiusMax_ = rMax;
    const scalar cutoff = pairCutoff();

    // this processor's particles (0 .. nOwn - 1), then the ghosts
    const labelListList send =
        nearProcessors(ownX, cutoff, riser_.section().period());
    // what this processor sends the others in the plan: copies and bytes
    label copiesSent = 0;
    std::size_t bytesSent = 0;
    for (const labelList& s : send)
    {
        copiesSent += s.size();
    }
    List<List<scalar>> ghostData;
    {
        labelListList sendRows(send.size());
        forAll(send, proc)
        {
            sendRows[proc].setSize(nData*send[proc].size());
            forAll(send[proc], k)
            {
                for (label c = 0; c < nData; ++c)
                {
                    sendRows[proc][nData*k + c] = nData*send[proc][k] + c;
                }
            }
        }
        ghostData = exchanged(sendRows, ownData, bytesSent);
    }
    DynamicList<labelPair> keys(nOwn);
    DynamicList<vector> X(nOwn), U(nOwn);
    DynamicList<scalar> D(nOwn), M(nOwn);
    DynamicList<label> need(nOwn), injected(nOwn);
    auto add = [&](const scalar* d)
    {
        X.append(vector(d[0], d[1], d[2]));
        keys.append(labelPair(label(d[3]), label(d[4])));
        U.append(vector(d[5], d[6], d[7]));
        D.append(d[8]);
        M.append(d[9]);
        need.append(label(d[10]));
        injected.append(label(d[11]));
    };
    for (label i = 0; i < nOwn; ++i)
    {
        add(&ownData[nData*i]);
    }
    // (the ghosts of each processor in its order)
    labelListList ghostIndex(ghostData.size());
    forAll(ghostData, proc)
    {
        ghostIndex[proc].setSize(ghostData[proc].size()/nData);
        forAll(ghostIndex[proc], k)
        {
            ghostIndex[proc][k] = X.size();
            add(&ghostData[proc][nData*k]);
        }
    }
    const std::size_t n = X.size();
    std::vector<riser::Vector> x(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        x[i] = toCore(X[i]);
    }

    // clusters of particles that may touch within the step, each with its
    // largest need (the core's planner)
    riser::ClusterPlan plan(std::vector<long>(need.begin(), need.end()));
    forEachNearPair(x, cutoff, [&](std::size_t i, std::size_t j, scalar)
    {
        const label p = i, q = j;
        const scalar gap = pairGap(x[p], keys[p], 0.5*D[p], x[q], keys[q], 0.5*D[q]);
        if (gap > pairReach(0.5*D[p], 0.5*D[q]))
        {
            return;
        }
        if (gap <= 0 && (injected[p] || injected[q]))
        {
            FatalErrorInFunction
                << "particles " << keys[p].second() << " (processor "
                << keys[p].first() << ") at " << X[p] << " and "
                << keys[q].second() << " (processor " << keys[q].first()
                << ") at " << X[q] << ", of diameters " << D[p]
                << " and " << D[q] << ", are released touching or"
                << " overlapping each other: overlap " << -gap << " >= 0;"
                << " release them at least (d_p + d_q)/2 apart"
                << exit(FatalError);
        }
        // the largest impact speed the pair can reach in the step
        const scalar speed =
            max(mag(U[p]) + mag(U[q]), 2*uMax) + pairSpeedGain;
        const riser::ContactBody body = riser::pairBody(0.5*D[p], M[p], 0.5*D[q], M[q]);
        const scalar tc = pairLaw_->contactTime(body, max(speed, SMALL));
        const scalar needed = ceil(stepsPerContact_*dt/tc);
        checkNeeded
        (
            needed, keys[p], X[p], tc,
            "contact with particle " + Foam::name(keys[q].second())
          + " (processor " + Foam::name(keys[q].first()) + ")"
        );
        plan.join(i, j, max(label(needed), label(1)));
    });

    // each cluster's largest need, spread across the processors: each
    // processor raises the ghosts to the needs their own processors found,
    // until no need grows anywhere
    for (bool grown = true; grown; )
    {
        grown = plan.spread(nOwn);
        List<label> ownNeeds(nOwn);
        forAll(ownNeeds, i)
        {
            ownNeeds[i] = plan.need(i);
        }
        const List<List<label>> ghostNeed = exchanged(send, ownNeeds, bytesSent);
        forAll(ghostNeed, proc)
        {
            forAll(ghostNeed[proc], k)
            {
                grown = plan.raise(ghostIndex[proc][k], ghostNeed[proc][k]) || grown;
            }
        }
        reduce(grown, orOp<bool>());
    }
    if (Pstream::parRun())
    {
        Info<< "    riserContact: plan sent copies of "
            << returnReduce(copiesSent, sumOp<label>()) << " particle(s) near"
            << " other processors, "
            << returnReduce(scalar(bytesSent), sumOp<scalar>()) << " bytes" << endl;
    }
    for (label i = 0; i < nOwn; ++i)
    {
        needs_.set
        (
            keys[i],
            subCycleNeed
            {
                label(plan.need(i)),
                plan.clustered(i) || (aloneMeshFree_ && plan.need(i) > 0)
            }
        );
    }
}


// ************************************************************************* //
